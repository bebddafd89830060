// The graded size field (graded_sizes.hpp): a bounding-box tree over the sources, built by median
// splits along the longest side, queried by branch and bound.
#include "api/graded_sizes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace isopatch {
namespace {

/// Sources per leaf: a few distance evaluations are cheaper than another level of boxes.
constexpr std::uint32_t kLeafSources = 8;

/// The distance from p to the box b (0 inside).
double distance_to(const Box& b, const Vec3& p) {
  const Vec3 d = (b.lo - p).cwiseMax(p - b.hi).cwiseMax(Vec3::Zero());
  return d.norm();
}

Box empty_box() {
  return Box{Vec3::Constant(std::numeric_limits<double>::infinity()),
             Vec3::Constant(-std::numeric_limits<double>::infinity())};
}

}  // namespace

GradedSizes::GradedSizes(std::vector<SizeSource> sources, double largest, double grading)
    : largest_(largest) {
  std::erase_if(sources, [&](const SizeSource& s) { return !(s.size < largest); });
  for (SizeSource& s : sources)
    if (s.grading == 0.0) s.grading = grading;
  sources_ = std::move(sources);
  if (!sources_.empty()) {
    nodes_.reserve(2 * sources_.size() / kLeafSources + 2);
    build(0, static_cast<std::uint32_t>(sources_.size()));
  }
}

std::uint32_t GradedSizes::build(std::uint32_t first, std::uint32_t count) {
  const auto id = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(Node{});
  Box bounds = empty_box();
  double smallest = largest_, gentlest = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = first; i < first + count; ++i) {
    bounds.lo = bounds.lo.cwiseMin(sources_[i].point);
    bounds.hi = bounds.hi.cwiseMax(sources_[i].point);
    smallest = std::min(smallest, sources_[i].size);
    gentlest = std::min(gentlest, sources_[i].grading);
  }
  if (count <= kLeafSources) {
    nodes_[id] = Node{bounds, smallest, gentlest, first, count, 0, 0};
    return id;
  }
  int axis = 0;
  (bounds.hi - bounds.lo).maxCoeff(&axis);
  const auto begin = sources_.begin() + first, middle = begin + count / 2, end = begin + count;
  // Ties broken by the other coordinates and the size: the same tree for the same sources.
  std::nth_element(begin, middle, end, [axis](const SizeSource& a, const SizeSource& b) {
    const std::array<double, 4> ka{a.point[axis], a.point[(axis + 1) % 3], a.point[(axis + 2) % 3], a.size};
    const std::array<double, 4> kb{b.point[axis], b.point[(axis + 1) % 3], b.point[(axis + 2) % 3], b.size};
    return ka < kb;
  });
  const std::uint32_t left = build(first, count / 2);
  const std::uint32_t right = build(first + count / 2, count - count / 2);
  nodes_[id] = Node{bounds, smallest, gentlest, 0, 0, left, right};
  return id;
}

double GradedSizes::at(const Vec3& p) const {
  double size = largest_;
  if (nodes_.empty()) return size;
  std::array<std::uint32_t, 128> stack{};
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!(node.smallest + node.gentlest * distance_to(node.bounds, p) < size)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        size = std::min(size, sources_[i].size + sources_[i].grading * (p - sources_[i].point).norm());
      continue;
    }
    // The nearer child last on the stack, so it is searched first and prunes the other.
    const double dl = distance_to(nodes_[node.left].bounds, p),
                 dr = distance_to(nodes_[node.right].bounds, p);
    stack[top++] = dl <= dr ? node.right : node.left;
    stack[top++] = dl <= dr ? node.left : node.right;
  }
  return size;
}

double GradedSizes::smallest() const {
  return nodes_.empty() ? largest_ : nodes_[0].smallest;
}

Box GradedSizes::extent() const {
  return nodes_.empty() ? empty_box() : nodes_[0].bounds;
}

}  // namespace isopatch
