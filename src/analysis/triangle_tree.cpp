// The self-intersection check's tree of triangles, see triangle_tree.hpp.
#include "analysis/triangle_tree.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "analysis/mesh_neighbourhood.hpp"
#include "core/spatial_order.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

namespace isopatch::analysis {
namespace {

/// x rounded to a float no larger than x, without branches (the direction of the rounding is a coin
/// toss per coordinate, and the branches of a step by std::nextafter were a sixth of the check's time):
/// the nearest float, stepped once towards -infinity when it lies above x. Above x it is positive (its
/// bits less one) or negative or -0 (its bits plus one: -0 becomes the negative float nearest 0).
float round_down(double x) {
  const auto nearest = static_cast<float>(x);
  auto bits = std::bit_cast<std::uint32_t>(nearest);
  const auto above = static_cast<std::uint32_t>(static_cast<double>(nearest) > x);
  bits += above * ((bits >> 31U) * 2U - 1U);  // +-1, as unsigned arithmetic wraps
  return std::bit_cast<float>(bits);
}
/// x rounded to a float no smaller than x.
float round_up(double x) {
  return -round_down(-x);
}

}  // namespace

void FloatBox::add(const Vec3& lo_d, const Vec3& hi_d) {
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::min(lo[a], round_down(lo_d[a]));
    hi[a] = std::max(hi[a], round_up(hi_d[a]));
  }
}

std::vector<std::uint32_t> z_ordered_triangles(const Mesh& mesh) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const ZOrderCube cube(lo, mesh.positions.empty() ? 0.0 : (hi - lo).maxCoeff());
  // One 64-bit integer per triangle: the top 32 of the key's 63 bits (a cell about 1/1600 of the box
  // across), then the index, which breaks ties. Half the bytes of a (key, index) pair to sort: the sort
  // was a fifth of the check's time.
  constexpr std::uint64_t kSkipped = std::numeric_limits<std::uint64_t>::max();  // after every triangle
  std::vector<std::uint64_t> keyed(mesh.triangles.size());
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, keyed.size(), std::size_t{1} << 14U), [&](const auto& r) {
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          const Triangle& tri = mesh.triangles[t];
          keyed[t] =
              repeats_vertex(tri)
                  ? kSkipped
                  : (cube.key((mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) /
                              3.0) >>
                     31U) << 32U |
                        t;
        }
      });
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order;
  order.reserve(keyed.size());
  for (const std::uint64_t k : keyed)
    if (k != kSkipped) order.push_back(static_cast<std::uint32_t>(k));
  return order;
}

std::vector<std::uint32_t> own_order(const Mesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  const bool any_repeats = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, 1U << 14U), false,
      [&](const auto& range, bool found) {
        for (std::size_t t = range.begin(); t != range.end() && !found; ++t)
          found = repeats_vertex(mesh.triangles[t]);
        return found;
      },
      [](bool a, bool b) { return a || b; });
  if (!any_repeats) {  // all of them, filled in parallel
    std::vector<std::uint32_t> order(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1U << 14U), [&](const auto& range) {
      for (std::size_t t = range.begin(); t != range.end(); ++t) order[t] = static_cast<std::uint32_t>(t);
    });
    return order;
  }
  std::vector<std::uint32_t> order;
  order.reserve(n);
  for (std::size_t t = 0; t < n; ++t)
    if (!repeats_vertex(mesh.triangles[t])) order.push_back(static_cast<std::uint32_t>(t));
  return order;
}

bool keeps_neighbours_together(const Mesh& mesh, const std::vector<std::uint32_t>& order) {
  constexpr std::size_t kGroup = 32;
  std::vector<double> groups, singles;
  const auto diagonal = [&](std::size_t begin, std::size_t end) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (std::size_t k = begin; k < end; ++k)
      for (const std::uint32_t v : mesh.triangles[order[k]]) {
        lo = lo.cwiseMin(mesh.positions[v]);
        hi = hi.cwiseMax(mesh.positions[v]);
      }
    return (hi - lo).norm();
  };
  // Every eighth group: the medians of a sample of thousands on large meshes, all of them on small ones.
  const std::size_t stride = order.size() >= 64 * kGroup * 8 ? 8 * kGroup : kGroup;
  for (std::size_t k = 0; k + kGroup <= order.size(); k += stride) {
    groups.push_back(diagonal(k, k + kGroup));
    singles.push_back(diagonal(k, k + 1));
  }
  if (groups.empty()) return true;
  const auto median = [](std::vector<double>& values) {
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2),
                     values.end());
    return values[values.size() / 2];
  };
  return median(groups) <= kLocalGroupSpan * median(singles);
}

TriangleTree::TriangleTree(const Mesh& mesh, std::vector<std::uint32_t> order,
                           const std::vector<std::uint8_t>* turns)
    : mesh_(mesh), order_(std::move(order)) {
  nodes_.resize(node_count(order_.size()));
  if (!order_.empty()) build(0, 0, order_.size(), turns);
}

void TriangleTree::make_boxes() {
  const std::size_t n = order_.size();
  for (std::size_t a = 0; a < 3; ++a) {  // written by box_subtree on the threads that fill them
    boxes_.lo[a].resize(n + kPadding);
    boxes_.hi[a].resize(n + kPadding);
    for (std::size_t k = n; k < n + kPadding; ++k) boxes_.lo[a][k] = boxes_.hi[a][k] = 0.0F;  // masked off
  }
  if (n > 0) box_subtree(0);
  boxed_ = true;
}

void TriangleTree::box_subtree(std::size_t index) {
  Node& node = nodes_[index];
  node.box = FloatBox{};
  if (node.leaf()) {
    for (std::size_t k = node.begin; k < node.end; ++k) {
      const FloatBox box = triangle_box(k);
      for (std::size_t a = 0; a < 3; ++a) {
        boxes_.lo[a][k] = box.lo[static_cast<Eigen::Index>(a)];
        boxes_.hi[a][k] = box.hi[static_cast<Eigen::Index>(a)];
      }
      node.box.add(box);
    }
    return;
  }
  if (node.end - node.begin >= kParallelBuild)
    tbb::parallel_invoke([&] { box_subtree(index + 1); }, [&] { box_subtree(node.right); });
  else {
    box_subtree(index + 1);
    box_subtree(node.right);
  }
  node.box = nodes_[index + 1].box;
  node.box.add(nodes_[node.right].box);
}

FloatBox TriangleTree::triangle_box(std::size_t position) const {
  const Triangle& tri = mesh_.triangles[order_[position]];
  const Vec3& p = mesh_.positions[tri[0]];
  const Vec3& q = mesh_.positions[tri[1]];
  const Vec3& r = mesh_.positions[tri[2]];
  FloatBox box;
  box.add(p.cwiseMin(q).cwiseMin(r), p.cwiseMax(q).cwiseMax(r));
  return box;
}

std::size_t TriangleTree::node_count(std::size_t n) {
  if (n <= kLeafSize) return n > 0 ? 1 : 0;
  return 1 + node_count(n / 2) + node_count(n - n / 2);
}

/// The subtree over positions [begin, end) at nodes_[index] (its nodes at index..index +
/// node_count(end - begin) - 1, depth first). The positions are in Z-order (or an order as local), so
/// halving the range halves the triangles in space, like a median split, at no cost.
/// Node numbers are fixed in advance, so the tree is the same for any number of threads.
void TriangleTree::build(std::size_t index, std::size_t begin, std::size_t end,
                         const std::vector<std::uint8_t>* turns) {
  Node& node = nodes_[index];
  node.begin = static_cast<std::uint32_t>(begin);
  node.end = static_cast<std::uint32_t>(end);
  if (end - begin <= kLeafSize) {
    node.turns = turns != nullptr ? std::uint8_t{0x3FU} : std::uint8_t{0};
    if (turns != nullptr)
      for (std::size_t k = begin; k < end; ++k) node.turns &= (*turns)[order_[k]];
    return;
  }
  const std::size_t middle = begin + (end - begin) / 2;
  const std::size_t left = index + 1;
  const std::size_t right = left + node_count(middle - begin);
  node.right = static_cast<std::uint32_t>(right);
  if (end - begin >= kParallelBuild)
    tbb::parallel_invoke([&] { build(left, begin, middle, turns); },
                         [&] { build(right, middle, end, turns); });
  else {
    build(left, begin, middle, turns);
    build(right, middle, end, turns);
  }
  node.turns = nodes_[left].turns & nodes_[right].turns;
}

std::vector<TriangleTree::Job> TriangleTree::jobs(std::size_t grain) const {
  if (!boxed_) throw std::logic_error("TriangleTree::jobs before make_boxes");
  std::vector<Job> out;
  if (!nodes_.empty()) self_jobs(0, grain, out);
  return out;
}

void TriangleTree::self_jobs(std::size_t n, std::size_t grain, std::vector<Job>& out) const {
  const Node& node = nodes_[n];
  if (node.proved) return;  // no pair within it meets
  if (node.leaf() || node.end - node.begin <= grain) {
    out.push_back({n, n, true});
    return;
  }
  self_jobs(n + 1, grain, out);  // the order of self_pairs
  self_jobs(node.right, grain, out);
  cross_jobs(n + 1, node.right, grain, out);
}

void TriangleTree::cross_jobs(std::size_t m, std::size_t n, std::size_t grain, std::vector<Job>& out) const {
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

std::size_t TriangleTree::proved_triangles() const {
  std::size_t count = 0;
  for (const Node& node : nodes_)
    if (node.proved) count += node.end - node.begin;  // proved nodes do not nest
  return count;
}

}  // namespace isopatch::analysis
