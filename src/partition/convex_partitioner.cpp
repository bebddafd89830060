// Partitions of convex cells behind the Partitioner interface (convex_partitioner.hpp).
#include "partition/convex_partitioner.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "partition/convex_overlay.hpp"
#include "partition/point_index.hpp"
#include "surface/sign_rule.hpp"

namespace isopatch {
namespace {

double magnitude_of(const Box& box) {
  return std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff());
}

std::array<Vec3, 8> box_corners(const Box& b) {
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i)
    c[static_cast<std::size_t>(i)] =
        Vec3((i & 1) ? b.hi.x() : b.lo.x(), (i & 2) ? b.hi.y() : b.lo.y(), (i & 4) ? b.hi.z() : b.lo.z());
  return c;
}

/// Whether f may vanish in the box: the interval bound where the surface gives one, else the
/// first-order test of the octree's descent (corners and centre of one sign, |f(centre)| above twice
/// the largest gradient times the half-diagonal: empty).
bool may_hold_surface(const Surface& surface, const Box& box) {
  if (const auto bound = surface.bound(box)) return bound->contains_zero();
  const Vec3 centre = box.centre();
  const ValueGradient c = surface.value_gradient(centre);
  double lipschitz = c.gradient.norm();
  const bool negative = is_negative(c.value);
  for (const Vec3& p : box_corners(box)) {
    const ValueGradient vg = surface.value_gradient(p);
    if (!std::isfinite(vg.value)) return true;
    if (is_negative(vg.value) != negative) return true;
    lipschitz = std::max(lipschitz, vg.gradient.norm());
  }
  return !(std::abs(c.value) > 2.0 * lipschitz * 0.5 * box.diagonal());
}

bool mixed_signs(const Surface& surface, const ConvexCell& cell) {
  bool neg = false, pos = false;
  for (const Vec3& p : cell.vertices()) (is_negative(surface.value(p)) ? neg : pos) = true;
  return neg && pos;
}

}  // namespace

ConvexPartitioner::ConvexPartitioner(const Surface& surface, const Box& box,
                                     const ConvexPartitionerSettings& settings)
    : surface_(surface), box_(box), settings_(settings) {
  if (!box.valid()) throw InputError("convex partition: the box must be finite with lo < hi on every axis");
  if (settings.start_level < 0 || settings.max_level < settings.start_level ||
      settings.max_level > kMaxPartitionLevel)
    throw InputError("convex partition: levels must satisfy 0 <= start <= max <= " +
                     std::to_string(kMaxPartitionLevel));
}

ConvexPartitioner ConvexPartitioner::clipped_lattice(const Surface& surface, const Box& box,
                                                     std::vector<CellPlane> region,
                                                     const ConvexPartitionerSettings& settings) {
  ConvexPartitioner p(surface, box, settings);
  p.region_ = std::move(region);
  p.lattice_mode_ = true;
  p.lattice_ = make_lattice(box, settings.max_level);
  p.lattice_.clip = box;
  intersect_half_spaces(box, p.region_);  // throws when the region leaves nothing of the box
  p.restart();
  return p;
}

ConvexPartitioner ConvexPartitioner::given_cells(const Surface& surface, const Box& box,
                                                 const std::vector<std::vector<CellPlane>>& cells,
                                                 const ConvexPartitionerSettings& settings) {
  ConvexPartitioner p(surface, box, settings);
  if (cells.empty()) throw InputError("convex partition: no cells given");
  for (std::size_t i = 0; i < cells.size(); ++i) {
    try {
      ConvexCell cell = intersect_half_spaces(box, cells[i]);
      const double size = cell.bounds().size().maxCoeff();
      p.given_.push_back(ConvexLeaf{std::move(cell), 0, size});
    } catch (const InputError&) {
      throw InputError("convex partition: cell " + std::to_string(i) + " has no volume inside the box");
    }
  }
  // Overlaps: a cell clipped by another's planes keeps volume. Candidate pairs by a sweep along x.
  std::vector<Box> bounds;
  std::vector<std::size_t> order(p.given_.size());
  for (std::size_t i = 0; i < p.given_.size(); ++i) {
    bounds.push_back(p.given_[i].cell.bounds());
    order[i] = i;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return bounds[a].lo.x() < bounds[b].lo.x() || (bounds[a].lo.x() == bounds[b].lo.x() && a < b);
  });
  for (std::size_t oi = 0; oi < order.size(); ++oi)
    for (std::size_t oj = oi + 1; oj < order.size() && bounds[order[oj]].lo.x() < bounds[order[oi]].hi.x();
         ++oj) {
      const std::size_t i = std::min(order[oi], order[oj]), j = std::max(order[oi], order[oj]);
      const Box &a = bounds[i], &b = bounds[j];
      if ((a.lo.array() >= b.hi.array()).any() || (b.lo.array() >= a.hi.array()).any()) continue;
      ConvexCell common = p.given_[i].cell;
      const ConvexCell& other = p.given_[j].cell;
      for (const ConvexCell::Face& face : other.faces())
        if (!common.clip(other.planes()[face.plane])) break;
      const double smaller = std::min(p.given_[i].cell.volume(), other.volume());
      if (!common.empty() && common.volume() > 1e-9 * smaller)
        throw InputError("convex partition: cells " + std::to_string(i) + " and " + std::to_string(j) +
                         " overlap");
    }
  // Gaps: every face is covered by neighbours completely, or not at all (the outer boundary).
  std::vector<ConvexCell> all;
  double smallest = std::numeric_limits<double>::infinity();
  for (const ConvexLeaf& leaf : p.given_) {
    all.push_back(leaf.cell);
    smallest = std::min(smallest, leaf.size);
  }
  PointIndex points(
      box.lo, box.size().maxCoeff() / 8.0,
      std::max(1e-9 * smallest, 1024.0 * std::numeric_limits<double>::epsilon() * magnitude_of(box)));
  overlay_cells(all, std::vector<bool>(all.size(), true), points, true);
  p.restart();
  return p;
}

bool ConvexPartitioner::lattice_leaf(int depth, const LatticePoint& coords, Leaf& out) const {
  if (!lattice_.inside(depth, coords)) return false;
  const Box b = lattice_.cell_box(depth, coords);
  const double size = lattice_.unit() * lattice_.step(depth);
  ConvexCell cell = ConvexCell::box(b, cell_tolerance(size, magnitude_of(box_)));
  for (const CellPlane& plane : region_)
    if (!cell.clip(plane)) return false;
  if (!(cell.volume() > 1e-9 * size * size * size)) return false;
  out = Leaf{ConvexLeaf{std::move(cell), depth, size}, true, depth, coords};
  return true;
}

void ConvexPartitioner::start_lattice() {
  const int depth = settings_.start_level;
  const std::uint32_t count = 1u << depth;
  const double tol = cell_tolerance(lattice_.unit(), magnitude_of(box_));
  // Descent: cubes that may hold the surface and are not beyond a region plane.
  std::set<LatticePoint> candidates;
  std::vector<std::pair<int, LatticePoint>> stack{{0, LatticePoint{0, 0, 0}}};
  while (!stack.empty()) {
    if (settings_.cancel && settings_.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled");
    const auto [d, c] = stack.back();
    stack.pop_back();
    if (!lattice_.inside(d, c)) continue;
    const Box b = lattice_.cell_box(d, c);
    const auto corners = box_corners(b);
    const bool outside = std::any_of(region_.begin(), region_.end(), [&](const CellPlane& plane) {
      return std::all_of(corners.begin(), corners.end(),
                         [&](const Vec3& p) { return plane.distance(p) > tol; });
    });
    if (outside || !may_hold_surface(surface_, b)) continue;
    if (d == depth) {
      candidates.insert(c);
      continue;
    }
    for (std::uint32_t i = 0; i < 8; ++i)
      stack.push_back(
          {d + 1, LatticePoint{2 * c[0] + (i & 1), 2 * c[1] + ((i >> 1) & 1), 2 * c[2] + ((i >> 2) & 1)}});
  }
  // The cubes with a sign change and all their neighbours (so every face of a cell that holds the
  // surface meets its neighbour), grown while a neighbour turns out to hold a sign change too.
  std::map<LatticePoint, Leaf> chosen;
  std::set<LatticePoint> tried;
  std::vector<LatticePoint> frontier;
  for (const LatticePoint& c : candidates) {
    tried.insert(c);
    Leaf leaf;
    if (lattice_leaf(depth, c, leaf)) {
      chosen.emplace(c, std::move(leaf));
      frontier.push_back(c);
    }
  }
  while (!frontier.empty()) {
    std::vector<LatticePoint> next;
    for (const LatticePoint& c : frontier)
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const std::int64_t x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
            if (x < 0 || y < 0 || z < 0 || x >= count || y >= count || z >= count) continue;
            const LatticePoint n{static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                                 static_cast<std::uint32_t>(z)};
            if (!tried.insert(n).second) continue;
            Leaf leaf;
            if (!lattice_leaf(depth, n, leaf)) continue;
            if (mixed_signs(surface_, leaf.leaf.cell)) next.push_back(n);
            chosen.emplace(n, std::move(leaf));
          }
    frontier = std::move(next);
  }
  leaves_.clear();
  for (auto& [c, leaf] : chosen) leaves_.push_back(std::move(leaf));
}

void ConvexPartitioner::restart() {
  to_split_.clear();
  if (lattice_mode_) {
    start_lattice();
    return;
  }
  leaves_.clear();
  for (const ConvexLeaf& g : given_) leaves_.push_back(Leaf{g, false, 0, {}});
  for (int level = 0; level < settings_.start_level; ++level) {
    std::vector<Leaf> finer;
    for (const Leaf& leaf : leaves_)
      for (Leaf& child : children(leaf)) finer.push_back(std::move(child));
    leaves_ = std::move(finer);
  }
}

std::vector<ConvexPartitioner::Leaf> ConvexPartitioner::children(const Leaf& leaf) const {
  std::vector<Leaf> out;
  if (leaf.on_lattice) {
    for (std::uint32_t i = 0; i < 8; ++i) {
      const LatticePoint c{2 * leaf.coords[0] + (i & 1), 2 * leaf.coords[1] + ((i >> 1) & 1),
                           2 * leaf.coords[2] + ((i >> 2) & 1)};
      Leaf child;
      if (lattice_leaf(leaf.depth + 1, c, child)) out.push_back(std::move(child));
    }
    return out;
  }
  // Three planes through the centre of the bounds, one per axis.
  const Vec3 centre = leaf.leaf.cell.bounds().centre();
  for (int i = 0; i < 8; ++i) {
    ConvexCell cell = leaf.leaf.cell;
    bool kept = true;
    for (int axis = 0; axis < 3 && kept; ++axis) {
      CellPlane plane;
      plane.normal = Vec3::Zero();
      const bool upper = ((i >> axis) & 1) != 0;
      plane.normal[axis] = upper ? -1.0 : 1.0;
      plane.offset = upper ? centre[axis] : -centre[axis];
      kept = cell.clip(plane);
    }
    if (kept && cell.volume() > 1e-9 * leaf.leaf.cell.volume())
      out.push_back(Leaf{
          ConvexLeaf{std::move(cell), leaf.leaf.level + 1, 0.5 * leaf.leaf.size}, false, leaf.depth + 1, {}});
  }
  return out;
}

CellPartition ConvexPartitioner::build() {
  if (!to_split_.empty()) {
    std::vector<bool> split(leaves_.size(), false);
    for (std::size_t i : to_split_) split[i] = true;
    std::vector<Leaf> next;
    for (std::size_t i = 0; i < leaves_.size(); ++i) {
      if (!split[i] || leaves_[i].leaf.level >= settings_.max_level) {
        next.push_back(std::move(leaves_[i]));
        continue;
      }
      for (Leaf& child : children(leaves_[i])) next.push_back(std::move(child));
    }
    leaves_ = std::move(next);
    to_split_.clear();
  }
  std::vector<ConvexLeaf> leaves;
  leaves.reserve(leaves_.size());
  for (const Leaf& leaf : leaves_) leaves.push_back(leaf.leaf);
  ConvexPartitionSettings s;
  s.edge_samples = settings_.edge_samples;
  s.cone_angle_deg = settings_.cone_angle_deg;
  s.start_level = settings_.start_level;
  s.strict = !lattice_mode_;
  s.cancel = settings_.cancel;
  return build_convex_partition(surface_, box_, leaves, s, &last_cells_);
}

bool ConvexPartitioner::start_finer() {
  if (settings_.start_level >= settings_.max_level) return false;
  ++settings_.start_level;
  restart();
  return true;
}

void ConvexPartitioner::split(std::span<const std::size_t> cells) {
  for (std::size_t c : cells) {
    if (c >= last_cells_.size())
      throw Error(ErrorKind::Internal, "convex partition: split of an unknown cell");
    to_split_.push_back(last_cells_[c]);
  }
}

}  // namespace isopatch
