#pragma once
// The self-intersection check's tree of triangles: a bounding volume hierarchy over the triangles in
// Z-order of their centroids, each range halved (a linear BVH: Lauterbach et al., "Fast BVH
// construction on GPUs", Eurographics 2009), traversed against itself so that every pair of
// overlapping boxes is met once. The triangles' boxes are kept by position, coordinate by coordinate,
// so that a leaf's triangles are tested against another's in one vectorised pass. (Making them again
// for each piece of the scan instead saves their 24 bytes per triangle but took 1.5 times as long.)

#include <isopatch/mesh.hpp>

#include "core/default_init_allocator.hpp"

#include <Eigen/Core>

#include <tbb/parallel_invoke.h>

#ifdef __SSE2__
#include <immintrin.h>
#endif

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace isopatch::analysis {

/// The triangles of `mesh` without a repeated vertex, in Z-order of their centroids (in cells of about
/// 1/1600 of the box, ties by index):
/// neighbours in space are mostly neighbours in the order. Sorted in parallel; the same order for any
/// number of threads. \pre check_mesh passed; fewer than 2^32 triangles.
std::vector<std::uint32_t> z_ordered_triangles(const Mesh& mesh);

/// The triangles of `mesh` without a repeated vertex, in the mesh's own order.
std::vector<std::uint32_t> own_order(const Mesh& mesh);

/// Whether `order` keeps neighbours together as a tree needs: the median box of 32 triangles in a row at
/// most kLocalGroupSpan times the median triangle's box across (meshers write about 6; a shuffled mesh
/// gives hundreds). Either way the tree finds the same pairs; in a good order of its own, a mesh saves
/// the sort and is read in order.
bool keeps_neighbours_together(const Mesh& mesh, const std::vector<std::uint32_t>& order);
constexpr double kLocalGroupSpan = 12.0;

/// A box in floats rounded outwards from doubles: it holds the boxes added to it, so overlaps are
/// never missed (the exact triangle test decides); half the memory of doubles.
struct FloatBox {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector3f hi = Eigen::Vector3f::Constant(-std::numeric_limits<float>::infinity());
  /// Grows the box to hold [lo, hi] (doubles).
  void add(const Vec3& lo_d, const Vec3& hi_d);
  void add(const FloatBox& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  bool overlaps(const FloatBox& b) const {
    return lo.x() <= b.hi.x() && lo.y() <= b.hi.y() && lo.z() <= b.hi.z() && b.lo.x() <= hi.x() &&
           b.lo.y() <= hi.y() && b.lo.z() <= hi.z();
  }
};

class TriangleTree {
 public:
  /// Leaves hold at most this many triangles (between half of it and it, the splits being halves).
  static constexpr std::size_t kLeafSize = 31;
  static_assert(kLeafSize < 32, "a leaf's overlaps are bits of an unsigned");
  /// Subtrees of at least this many triangles are built in parallel.
  static constexpr std::size_t kParallelBuild = std::size_t{1} << 14;

  /// The tree over the triangles `order` of `mesh` (z_ordered_triangles, or an order as local); `mesh`
  /// must outlive it. `turns` (optional, MeshFans::triangle_turns) gives each node the turn bits all its
  /// triangles have. Its boxes come with make_boxes. Memory: 4 bytes per triangle and a 40-byte node per
  /// 8 to 16 triangles (two nodes per leaf of 16 to 31).
  TriangleTree(const Mesh& mesh, std::vector<std::uint32_t> order,
               const std::vector<std::uint8_t>* turns = nullptr);
  /// The boxes of the triangles and nodes, which jobs() and run() need: 24 bytes per triangle. Made
  /// after the proofs, whose data is then freed, so that the two are not held at once.
  void make_boxes();

  /// Marks the largest subtrees of at least `smallest` triangles for which prove(begin, end, turns)
  /// holds (positions [begin, end), the turn bits all their triangles share, when there are some): a
  /// proof that they hold no pair that meets (flat_discs.hpp). The scan then skips the pairs within
  /// them. Subtrees are proved in parallel; the marks do not depend on the number of threads.
  template <class Prove>
  void prove_subtrees(const Prove& prove, std::size_t smallest) {
    if (!nodes_.empty()) prove_from(0, prove, smallest);
  }
  /// Triangles in subtrees marked by prove_subtrees.
  std::size_t proved_triangles() const;
  /// Calls f(begin, end) for the positions of every leaf outside the subtrees marked by prove_subtrees,
  /// in order.
  template <class F>
  void for_each_unproved_leaf(F&& f) const {
    if (!nodes_.empty()) unproved_leaves(0, f);
  }
  /// The triangle at each position.
  const std::vector<std::uint32_t>& order() const { return order_; }

  /// A piece of the scan: the pairs within node m (self) or between nodes m and n.
  struct Job {
    std::size_t m = 0, n = 0;
    bool self = false;
  };
  /// The scan cut into pieces of at most about `grain` triangles (or single leaves), in the order of
  /// one whole scan. \throw std::logic_error before make_boxes.
  std::vector<Job> jobs(std::size_t grain) const;
  /// Calls visit(a, b) with the positions of triangles whose boxes overlap, for the pairs of one job
  /// that no proof excludes, until it returns false; false then. Over all jobs, each such pair once.
  template <class Visit>
  bool run(const Job& job, Visit&& visit) const {
    return job.self ? self_pairs(job.m, visit) : cross_pairs(job.m, job.n, visit);
  }
  /// The index in the mesh of the triangle at a position.
  std::uint32_t triangle(std::size_t position) const { return order_[position]; }

 private:
  struct Node {
    FloatBox box;
    std::uint32_t begin = 0, end = 0;  // triangle positions
    std::uint32_t right = 0;  // the right child of an inner node (the left one follows it); 0 for leaves
    std::uint8_t turns = 0;   // the turn bits of all its triangles
    bool proved = false;      // no pair within it meets (prove_subtrees)
    bool leaf() const { return right == 0; }
  };

  template <class F>
  void unproved_leaves(std::size_t n, F& f) const {
    const Node& node = nodes_[n];
    if (node.proved) return;
    if (node.leaf()) {
      f(node.begin, node.end);
      return;
    }
    unproved_leaves(n + 1, f);
    unproved_leaves(node.right, f);
  }

  template <class Prove>
  void prove_from(std::size_t n, const Prove& prove, std::size_t smallest) {
    Node& node = nodes_[n];
    if (node.end - node.begin < smallest) return;
    if ((node.turns & 0x3FU) != 0 && prove(node.begin, node.end, node.turns)) {
      node.proved = true;
      return;
    }
    if (node.leaf()) return;
    if (node.end - node.begin >= kParallelBuild)
      tbb::parallel_invoke([&] { prove_from(n + 1, prove, smallest); },
                           [&] { prove_from(node.right, prove, smallest); });
    else {
      prove_from(n + 1, prove, smallest);
      prove_from(node.right, prove, smallest);
    }
  }

  static std::size_t node_count(std::size_t n);
  FloatBox triangle_box(std::size_t position) const;
  void self_jobs(std::size_t n, std::size_t grain, std::vector<Job>& out) const;
  void cross_jobs(std::size_t m, std::size_t n, std::size_t grain, std::vector<Job>& out) const;
  static bool splits_first(const Node& a, const Node& b) {
    return !a.leaf() && (b.leaf() || a.end - a.begin >= b.end - b.begin);
  }

  /// The triangles' boxes by position, coordinate by coordinate.
  struct Boxes {
    UninitialisedVector<float> lo[3], hi[3];
  };

  /// Bit k - begin for the positions k in [begin, end) (at most kLeafSize of them) whose triangle's box
  /// overlaps `box`: four positions per SSE comparison (the box arrays are padded by kPadding, and the
  /// bits past end masked off). GCC did not vectorise the loop of single comparisons, and this test is
  /// most of the traversal's time.
  unsigned overlapping(const FloatBox& box, std::uint32_t begin, std::uint32_t end) const {
    unsigned bits = 0;
#ifdef __SSE2__
    const __m128 lo_x = _mm_set1_ps(box.lo.x()), lo_y = _mm_set1_ps(box.lo.y()),
                 lo_z = _mm_set1_ps(box.lo.z());
    const __m128 hi_x = _mm_set1_ps(box.hi.x()), hi_y = _mm_set1_ps(box.hi.y()),
                 hi_z = _mm_set1_ps(box.hi.z());
    for (std::uint32_t k = begin; k < end; k += 4) {
      __m128 m = _mm_cmple_ps(_mm_loadu_ps(&boxes_.lo[0][k]), hi_x);
      m = _mm_and_ps(m, _mm_cmple_ps(_mm_loadu_ps(&boxes_.lo[1][k]), hi_y));
      m = _mm_and_ps(m, _mm_cmple_ps(_mm_loadu_ps(&boxes_.lo[2][k]), hi_z));
      m = _mm_and_ps(m, _mm_cmple_ps(lo_x, _mm_loadu_ps(&boxes_.hi[0][k])));
      m = _mm_and_ps(m, _mm_cmple_ps(lo_y, _mm_loadu_ps(&boxes_.hi[1][k])));
      m = _mm_and_ps(m, _mm_cmple_ps(lo_z, _mm_loadu_ps(&boxes_.hi[2][k])));
      bits |= static_cast<unsigned>(_mm_movemask_ps(m)) << (k - begin);
    }
    return bits & ((1U << (end - begin)) - 1U);
#else
    for (std::uint32_t k = begin; k < end; ++k) {
      const auto below = [](float a, float b) { return static_cast<unsigned>(a <= b); };
      const unsigned overlap = below(boxes_.lo[0][k], box.hi.x()) & below(boxes_.lo[1][k], box.hi.y()) &
                               below(boxes_.lo[2][k], box.hi.z()) & below(box.lo.x(), boxes_.hi[0][k]) &
                               below(box.lo.y(), boxes_.hi[1][k]) & below(box.lo.z(), boxes_.hi[2][k]);
      bits |= overlap << (k - begin);
    }
    return bits;
#endif
  }
  /// Entries past the last position in each box array, so that overlapping() may read four at a time.
  static constexpr std::size_t kPadding = 4;
  FloatBox box_at(std::uint32_t k) const {
    FloatBox box;
    for (std::size_t a = 0; a < 3; ++a) {
      box.lo[static_cast<Eigen::Index>(a)] = boxes_.lo[a][k];
      box.hi[static_cast<Eigen::Index>(a)] = boxes_.hi[a][k];
    }
    return box;
  }

  /// Visits the pairs (i, j), i in [a_begin, a_end) and j in [b_begin, b_end) with j > i when
  /// `self`, whose boxes overlap; false when visit does.
  template <class Visit>
  bool leaf_pairs(std::uint32_t a_begin, std::uint32_t a_end, std::uint32_t b_begin, std::uint32_t b_end,
                  bool self, Visit& visit) const {
    for (std::uint32_t i = a_begin; i < a_end; ++i) {
      const std::uint32_t from = self ? i + 1 : b_begin;
      for (unsigned bits = overlapping(box_at(i), from, b_end); bits != 0; bits &= bits - 1)
        if (!visit(i, from + static_cast<std::uint32_t>(__builtin_ctz(bits)))) return false;
    }
    return true;
  }

  template <class Visit>
  bool self_pairs(std::size_t n, Visit& visit) const {
    const Node& node = nodes_[n];
    if (node.proved) return true;
    if (node.leaf()) return leaf_pairs(node.begin, node.end, node.begin, node.end, true, visit);
    return self_pairs(n + 1, visit) && self_pairs(node.right, visit) && cross_pairs(n + 1, node.right, visit);
  }

  template <class Visit>
  bool cross_pairs(std::size_t m, std::size_t n, Visit& visit) const {
    const Node& a = nodes_[m];
    const Node& b = nodes_[n];
    if (!a.box.overlaps(b.box)) return true;
    if (a.leaf() && b.leaf()) return leaf_pairs(a.begin, a.end, b.begin, b.end, false, visit);
    if (splits_first(a, b)) return cross_pairs(m + 1, n, visit) && cross_pairs(a.right, n, visit);
    return cross_pairs(m, n + 1, visit) && cross_pairs(m, b.right, visit);
  }

  void build(std::size_t index, std::size_t begin, std::size_t end, const std::vector<std::uint8_t>* turns);
  void box_subtree(std::size_t index);

  const Mesh& mesh_;
  std::vector<std::uint32_t> order_;  // the triangle at each position
  std::vector<Node> nodes_;           // depth first
  Boxes boxes_;
  bool boxed_ = false;
};

}  // namespace isopatch::analysis
