// Self-intersection test of a triangle mesh (see include/isopatch/self_intersection.hpp): a bounding
// volume hierarchy over the triangles' boxes, traversed against itself so that every pair of
// overlapping boxes is met once; each such pair is decided by segment-against-triangle tests (two
// triangles in general position meet iff an edge of one meets the other, since each end of the segment
// where they meet lies on an edge of one of them).
#include <isopatch/error.hpp>
#include <isopatch/self_intersection.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "analysis/exact_predicates.hpp"
#include "analysis/mesh_neighbourhood.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace isopatch {
namespace {

/// Six times the signed volume of (a, b, c, d), rounded: for the position of a crossing only; every
/// decision uses the exact signs of exact_predicates.hpp.
double signed_volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a);
}

/// A point of the plane that drops one coordinate axis (the one where a triangle's normal is largest).
struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

Point2 drop_axis(const Vec3& v, int dropped) {
  const int i = (dropped + 1) % 3, j = (dropped + 2) % 3;
  return {v[i], v[j]};
}

int dominant_axis(const Vec3& n) {
  const Vec3 a = n.cwiseAbs();
  return a.x() >= a.y() ? (a.x() >= a.z() ? 0 : 2) : (a.y() >= a.z() ? 1 : 2);
}

int orient2d(Point2 a, Point2 b, Point2 c) {
  return exact::orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

/// Signs that are not strictly one positive and one negative.
bool opposite_or_zero(int s, int t) {
  return s * t <= 0;
}

/// Signs of which none is positive, or none negative.
bool one_side(int s1, int s2, int s3) {
  const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
  const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
  return !(negative && positive);
}

/// Closed segments pq and ab meet (touching and collinear overlap included).
bool segments_meet_2d(Point2 p, Point2 q, Point2 a, Point2 b) {
  const int d1 = orient2d(a, b, p), d2 = orient2d(a, b, q);
  if (d1 == 0 && d2 == 0) {  // collinear: overlap of the projections on the longer axis
    const bool use_x = std::abs(q.x - p.x) + std::abs(b.x - a.x) >= std::abs(q.y - p.y) + std::abs(b.y - a.y);
    const auto key = [use_x](Point2 v) { return use_x ? v.x : v.y; };
    return std::max(std::min(key(p), key(q)), std::min(key(a), key(b))) <=
           std::min(std::max(key(p), key(q)), std::max(key(a), key(b)));
  }
  return opposite_or_zero(d1, d2) && opposite_or_zero(orient2d(p, q, a), orient2d(p, q, b));
}

/// Closed triangle abc contains p.
bool contains_2d(Point2 a, Point2 b, Point2 c, Point2 p) {
  return one_side(orient2d(a, b, p), orient2d(b, c, p), orient2d(c, a, p));
}

/// The closed segment pq meets the closed triangle abc; *at receives a point they share.
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c,
                            Vec3* at) {
  const int sp = exact::orient3d(a, b, c, p), sq = exact::orient3d(a, b, c, q);
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) {  // in the triangle's plane: decide in 2D
    const Vec3 normal = (b - a).cross(c - a);
    if (normal.squaredNorm() == 0.0) return false;  // a degenerate triangle has no plane
    const int axis = dominant_axis(normal);
    const Point2 p2 = drop_axis(p, axis), q2 = drop_axis(q, axis);
    const Point2 a2 = drop_axis(a, axis), b2 = drop_axis(b, axis), c2 = drop_axis(c, axis);
    if (contains_2d(a2, b2, c2, p2)) {
      *at = p;
      return true;
    }
    if (contains_2d(a2, b2, c2, q2)) {
      *at = q;
      return true;
    }
    const Vec3* corners[3] = {&a, &b, &c};
    const Point2 corners2[3] = {a2, b2, c2};
    for (int e = 0; e < 3; ++e)
      if (segments_meet_2d(p2, q2, corners2[e], corners2[(e + 1) % 3])) {
        *at = 0.5 * (*corners[e] + *corners[(e + 1) % 3]);
        return true;
      }
    return false;
  }
  // The segment reaches the plane; the point where it does lies in the triangle iff the line pq passes
  // every edge on the same side.
  if (!one_side(exact::orient3d(p, q, a, b), exact::orient3d(p, q, b, c), exact::orient3d(p, q, c, a)))
    return false;
  const double dp = signed_volume6(a, b, c, p), dq = signed_volume6(a, b, c, q);
  *at = dp == dq ? p : Vec3(p + dp / (dp - dq) * (q - p));
  return true;
}

/// Triangles s and t of `mesh` meet other than in what they share by index (see the header).
bool triangles_meet(const Mesh& mesh, const Triangle& s, const Triangle& t, Vec3* at) {
  int shared = 0;
  int s_only[3], t_only[3];  // positions in s (t) of the vertices t (s) does not have
  int ns = 0, nt = 0;
  for (int i = 0; i < 3; ++i) {
    const bool in_t = s[i] == t[0] || s[i] == t[1] || s[i] == t[2];
    shared += in_t ? 1 : 0;
    if (!in_t) s_only[ns++] = i;
    const bool in_s = t[i] == s[0] || t[i] == s[1] || t[i] == s[2];
    if (!in_s) t_only[nt++] = i;
  }
  const auto& x = mesh.positions;
  const auto vertex = [&](const Triangle& tri, int i) -> const Vec3& {
    return x[tri[static_cast<std::size_t>(i)]];
  };
  const auto edge_meets = [&](const Triangle& a, int i, int j, const Triangle& b) {
    return segment_meets_triangle(vertex(a, i), vertex(a, j), vertex(b, 0), vertex(b, 1), vertex(b, 2), at);
  };
  switch (shared) {
    case 0:
      for (int i = 0; i < 3; ++i)
        if (edge_meets(s, i, (i + 1) % 3, t) || edge_meets(t, i, (i + 1) % 3, s)) return true;
      return false;
    case 1:
      // Meeting anywhere but the common vertex means meeting the edge opposite it in the other.
      return edge_meets(s, s_only[0], s_only[1], t) || edge_meets(t, t_only[0], t_only[1], s);
    case 2: {
      // Folded flat: the third vertices in the plane of the common edge, on the same side of it.
      const Vec3& u = vertex(s, (s_only[0] + 1) % 3);
      const Vec3& w = vertex(s, (s_only[0] + 2) % 3);
      const Vec3& a = vertex(s, s_only[0]);
      const Vec3& b = vertex(t, t_only[0]);
      if (exact::orient3d(u, w, a, b) != 0) return false;
      const Vec3 normal = (w - u).cross(a - u);
      if (normal.squaredNorm() == 0.0) return false;
      const int axis = dominant_axis(normal);
      const int side_a = orient2d(drop_axis(u, axis), drop_axis(w, axis), drop_axis(a, axis));
      const int side_b = orient2d(drop_axis(u, axis), drop_axis(w, axis), drop_axis(b, axis));
      if (side_a * side_b <= 0) return false;
      *at = u;
      return true;
    }
    default:
      *at = vertex(s, 0);
      return true;  // the same triangle twice
  }
}

/// x rounded to a float no larger (down) or no smaller (up) than x.
float round_down(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float round_up(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

/// A triangle's box, in doubles: computed when needed from the positions, so that the tree keeps no
/// box per triangle (a 1M-vertex mesh has 2M triangles: 48 MB of boxes otherwise).
struct TriangleBox {
  Vec3 lo, hi;
  TriangleBox() = default;
  TriangleBox(const Mesh& mesh, std::uint32_t t) {
    const Triangle& tri = mesh.triangles[t];
    lo = hi = mesh.positions[tri[0]];
    for (int k = 1; k < 3; ++k) {
      lo = lo.cwiseMin(mesh.positions[tri[static_cast<std::size_t>(k)]]);
      hi = hi.cwiseMax(mesh.positions[tri[static_cast<std::size_t>(k)]]);
    }
  }
  bool overlaps(const TriangleBox& b) const {
    return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all();
  }
};

/// A node's box in floats rounded outwards (it holds the triangles' double boxes, so overlaps are never
/// missed; the exact triangle test decides): half the memory of doubles.
struct BoxOf {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector3f hi = Eigen::Vector3f::Constant(-std::numeric_limits<float>::infinity());
  void add(const TriangleBox& b) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], round_down(b.lo[a]));
      hi[a] = std::max(hi[a], round_up(b.hi[a]));
    }
  }
  bool overlaps(const BoxOf& b) const {
    return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all();
  }
};

/// A bounding volume hierarchy over triangle boxes, median split on the longest axis of the centres.
/// Triangles per piece of the parallel pair scan: a few dozen pieces on a 20k-vertex mesh.
constexpr std::size_t kTrianglesPerJob = 1024;

class TriangleTree {
 public:
  /// Leaves hold at most this many triangles (between half of it and it, the splits being medians).
  static constexpr std::size_t kLeafSize = 8;
  /// Subtrees of at least this many triangles build their two halves in parallel.
  static constexpr std::size_t kParallelBuild = std::size_t{1} << 14;

  /// The tree over the triangles `order` of `mesh` (which must outlive it). Memory: 4 bytes per triangle
  /// and a 32-byte node per 3 to 4 triangles.
  TriangleTree(const Mesh& mesh, std::vector<std::uint32_t> order) : mesh_(mesh), order_(std::move(order)) {
    nodes_.resize(node_count(order_.size()));
    if (!order_.empty()) build(0, 0, order_.size());
  }

  /// Calls visit(i, j) once for every pair of triangles (i != j) whose boxes overlap, until it
  /// returns false.
  template <class Visit>
  void for_overlapping_pairs(Visit&& visit) const {
    if (!nodes_.empty()) self_pairs(0, visit);
  }

  /// A piece of that scan: the pairs within node m (self) or between nodes m and n.
  struct Job {
    std::size_t m = 0, n = 0;
    bool self = false;
  };
  /// The scan cut into pieces of at most about `grain` triangles (or single leaves), in the order the
  /// whole scan visits them: run(job) for each in turn visits the pairs of for_overlapping_pairs.
  std::vector<Job> jobs(std::size_t grain) const {
    std::vector<Job> out;
    if (!nodes_.empty()) self_jobs(0, grain, out);
    return out;
  }
  /// Calls visit(i, j) for the pairs of one job, until it returns false; false then.
  template <class Visit>
  bool run(const Job& job, Visit&& visit) const {
    return job.self ? self_pairs(job.m, visit) : cross_pairs(job.m, job.n, visit);
  }

 private:
  /// 36 bytes: nodes are stored depth first, so an inner node's left child follows it.
  struct Node {
    BoxOf box;
    std::uint32_t begin = 0, end = 0;  // triangle range in order_
    std::uint32_t right = 0;           // the right child of an inner node; 0 for leaves
    bool leaf() const { return right == 0; }
  };

  /// The nodes of a tree over n triangles (the splits of build()).
  static std::size_t node_count(std::size_t n) {
    if (n <= kLeafSize) return n > 0 ? 1 : 0;
    return 1 + node_count(n / 2) + node_count(n - n / 2);
  }

  /// Builds the subtree over order_[begin, end) at nodes_[index] (its nodes at index..index +
  /// node_count(end - begin) - 1, depth first). Splits at the median of the triangles' first corners
  /// along the longest axis of their spread (any split gives the same pairs; this one costs one
  /// position per triangle and level); boxes are made bottom-up, rounded once per leaf. Large subtrees
  /// are built in parallel: the node numbers are fixed in advance, so the tree is the same for any
  /// number of threads.
  void build(std::size_t index, std::size_t begin, std::size_t end) {
    Node& node = nodes_[index];
    node.begin = static_cast<std::uint32_t>(begin);
    node.end = static_cast<std::uint32_t>(end);
    if (end - begin <= kLeafSize) {
      TriangleBox box(mesh_, order_[begin]);
      for (std::size_t k = begin + 1; k < end; ++k) {
        const TriangleBox b(mesh_, order_[k]);
        box.lo = box.lo.cwiseMin(b.lo);
        box.hi = box.hi.cwiseMax(b.hi);
      }
      node.box.add(box);
      return;
    }
    const auto first_corner = [&](std::uint32_t t) -> const Vec3& {
      return mesh_.positions[mesh_.triangles[t][0]];
    };
    Vec3 lo = first_corner(order_[begin]), hi = lo;
    for (std::size_t k = begin + 1; k < end; ++k) {
      lo = lo.cwiseMin(first_corner(order_[k]));
      hi = hi.cwiseMax(first_corner(order_[k]));
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(
        order_.begin() + static_cast<std::ptrdiff_t>(begin),
        order_.begin() + static_cast<std::ptrdiff_t>(middle),
        order_.begin() + static_cast<std::ptrdiff_t>(end),
        [&](std::uint32_t a, std::uint32_t b) { return first_corner(a)[axis] < first_corner(b)[axis]; });
    const std::size_t left = index + 1;
    const std::size_t right = left + node_count(middle - begin);
    node.right = static_cast<std::uint32_t>(right);
    if (end - begin >= kParallelBuild)
      tbb::parallel_invoke([&] { build(left, begin, middle); }, [&] { build(right, middle, end); });
    else {
      build(left, begin, middle);
      build(right, middle, end);
    }
    node.box = nodes_[left].box;
    node.box.lo = node.box.lo.cwiseMin(nodes_[right].box.lo);
    node.box.hi = node.box.hi.cwiseMax(nodes_[right].box.hi);
  }

  void self_jobs(std::size_t n, std::size_t grain, std::vector<Job>& out) const {
    const Node& node = nodes_[n];
    if (node.leaf() || node.end - node.begin <= grain) {
      out.push_back({n, n, true});
      return;
    }
    self_jobs(n + 1, grain, out);  // the order of self_pairs
    self_jobs(node.right, grain, out);
    cross_jobs(n + 1, node.right, grain, out);
  }

  void cross_jobs(std::size_t m, std::size_t n, std::size_t grain, std::vector<Job>& out) const {
    const Node& a = nodes_[m];
    const Node& b = nodes_[n];
    if (!a.box.overlaps(b.box)) return;
    if ((a.leaf() && b.leaf()) || (a.end - a.begin) + (b.end - b.begin) <= grain) {
      out.push_back({m, n, false});
      return;
    }
    if (splits_first(a, b)) {  // the order of cross_pairs
      cross_jobs(m + 1, n, grain, out);
      cross_jobs(a.right, n, grain, out);
    } else {
      cross_jobs(m, n + 1, grain, out);
      cross_jobs(m, b.right, grain, out);
    }
  }

  /// Whether cross_pairs(a, b) descends into a (else into b).
  static bool splits_first(const Node& a, const Node& b) {
    return !a.leaf() && (b.leaf() || a.end - a.begin >= b.end - b.begin);
  }

  /// The boxes of a leaf's triangles, into `boxes` (kLeafSize of them); returns their count.
  std::size_t leaf_boxes(const Node& leaf, TriangleBox* boxes) const {
    for (std::uint32_t k = leaf.begin; k < leaf.end; ++k)
      boxes[k - leaf.begin] = TriangleBox(mesh_, order_[k]);
    return leaf.end - leaf.begin;
  }

  template <class Visit>
  bool self_pairs(std::size_t n, Visit& visit) const {
    const Node& node = nodes_[n];
    if (node.leaf()) {
      TriangleBox boxes[kLeafSize];
      const std::size_t count = leaf_boxes(node, boxes);
      for (std::size_t a = 0; a < count; ++a)
        for (std::size_t b = a + 1; b < count; ++b)
          if (boxes[a].overlaps(boxes[b]) && !visit(order_[node.begin + a], order_[node.begin + b]))
            return false;
      return true;
    }
    return self_pairs(n + 1, visit) && self_pairs(node.right, visit) && cross_pairs(n + 1, node.right, visit);
  }

  template <class Visit>
  bool cross_pairs(std::size_t m, std::size_t n, Visit& visit) const {
    const Node& a = nodes_[m];
    const Node& b = nodes_[n];
    if (!a.box.overlaps(b.box)) return true;
    if (a.leaf() && b.leaf()) {
      TriangleBox boxes_a[kLeafSize], boxes_b[kLeafSize];
      const std::size_t count_a = leaf_boxes(a, boxes_a), count_b = leaf_boxes(b, boxes_b);
      for (std::size_t i = 0; i < count_a; ++i)
        for (std::size_t j = 0; j < count_b; ++j)
          if (boxes_a[i].overlaps(boxes_b[j]) && !visit(order_[a.begin + i], order_[b.begin + j]))
            return false;
      return true;
    }
    if (splits_first(a, b)) return cross_pairs(m + 1, n, visit) && cross_pairs(a.right, n, visit);
    return cross_pairs(m, n + 1, visit) && cross_pairs(m, b.right, visit);
  }

  const Mesh& mesh_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace

SelfIntersectionReport find_self_intersections(const Mesh& mesh, std::size_t limit) {
  analysis::check_mesh(mesh, "find_self_intersections");
  if (mesh.triangles.size() >= std::numeric_limits<std::uint32_t>::max())
    throw InputError("find_self_intersections: more than 2^32 triangles");
  std::vector<std::uint32_t> order;
  order.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!analysis::repeats_vertex(mesh.triangles[t])) order.push_back(static_cast<std::uint32_t>(t));
  SelfIntersectionReport report;
  if (limit == 0) return report;
  const TriangleTree tree(mesh, std::move(order));
  // The scan in pieces, in parallel; each piece counts its own pairs (up to the limit) and keeps its
  // first. In the pieces' order, the first piece with a pair has the scan's first pair: the same report
  // as one scan, for any number of threads.
  struct Found {
    std::size_t pairs = 0;
    std::array<std::size_t, 2> example{};
    Vec3 at = Vec3::Zero();
  };
  const std::vector<TriangleTree::Job> jobs = tree.jobs(kTrianglesPerJob);
  std::vector<Found> found(jobs.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, jobs.size(), 1), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      Found& f = found[k];
      tree.run(jobs[k], [&](std::size_t i, std::size_t j) {
        Vec3 at;
        if (!triangles_meet(mesh, mesh.triangles[i], mesh.triangles[j], &at)) return true;
        if (f.pairs++ == 0) {
          f.example = {std::min(i, j), std::max(i, j)};
          f.at = at;
        }
        return f.pairs < limit;
      });
    }
  });
  std::size_t total = 0;
  for (const Found& f : found) {
    if (total == 0 && f.pairs > 0) {
      report.example = f.example;
      report.example_point = f.at;
    }
    total += f.pairs;
  }
  report.pairs = std::min(total, limit);
  report.capped = total >= limit;
  return report;
}

}  // namespace isopatch
