// The octree as a Partitioner (octree_partitioner.hpp).
#include "partition/octree_partitioner.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>

#include "core/cube_numbering.hpp"
#include "partition/cube_cycles.hpp"

namespace isopatch {
namespace {

/// A face whose every sample (corners and centre) lies within this share of the cell side of f = 0,
/// with grad f within acos(kGrazingNormal) of the face normal, holds the surface nearly in its plane.
constexpr double kGrazingDistance = 0.05;
constexpr double kGrazingNormal = 0.9;

/// Records that `cell` has a loop side on `face` (cells arrive in ascending order).
void add_cell(CellFace& face, std::uint32_t cell) {
  if (face.cells[0] == cell || face.cells[1] == cell) return;
  if (face.cells[0] == kNoCell) {
    face.cells[0] = cell;
  } else if (face.cells[1] == kNoCell) {
    face.cells[1] = cell;
  } else {
    throw Error(ErrorKind::Internal, "octree: a face with loop sides of three cells");
  }
}

}  // namespace

OctreeDepths plan_octree_depths(const Box& box, const OctreeDepthRequest& r) {
  const Lattice root = make_lattice(box, 0);
  const double ratio = std::log2(root.size / r.cell_length);
  const double wanted = r.closest ? std::round(ratio) : std::ceil(ratio - 1e-9);
  OctreeDepths depths;
  depths.limit = r.max_depth;
  // An edge length far below the finest cells leaves features of a few cells (a sphere of radius 0.01
  // in a box of side 2 at depth 8) no room to refine, and the fans that close rejected patches fold.
  if (r.raise_limit_by >= 0 && wanted >= r.max_depth)
    depths.limit = static_cast<int>(std::min<double>(kOctreeDepthLimit, wanted + r.raise_limit_by));
  if (r.finest_cell > 0.0)
    depths.limit =
        std::max(depths.limit, static_cast<int>(std::min<double>(
                                   kSizeFieldDepthLimit, std::ceil(std::log2(root.size / r.finest_cell)))));
  depths.start = static_cast<int>(
      std::clamp(wanted, static_cast<double>(r.min_depth), static_cast<double>(depths.limit)));
  return depths;
}

Box face_box(const Lattice& lattice, const FaceId& face) {
  LatticePoint upper = face.lower;
  for (std::uint32_t a = 0; a < 3; ++a)
    if (a != face.axis) upper[a] += face.size;
  return Box{lattice.point(face.lower), lattice.point(upper)};
}

CellPartition cell_partition_of(const Partition& octree) {
  CellPartition p;
  p.region = octree.lattice.clip;
  p.start_level = octree.surface_depth;
  p.stats = octree.stats;
  p.corners.reserve(octree.crossings.size());
  for (const Crossing& c : octree.crossings) p.corners.push_back({c.position, c.direction, c.gradient});
  std::vector<FaceId> ids;
  for (const Leaf& leaf : octree.leaves)
    for (const Loop& loop : leaf.loops) ids.insert(ids.end(), loop.side_faces.begin(), loop.side_faces.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  p.faces.reserve(ids.size());
  for (const FaceId& id : ids) {
    CellFace face;
    face.normal = Vec3::Unit(static_cast<Eigen::Index>(id.axis));
    face.axis = static_cast<int>(id.axis);
    face.region = face_box(octree.lattice, id);
    p.faces.push_back(face);
  }
  p.cells.reserve(octree.leaves.size());
  for (const Leaf& leaf : octree.leaves) {
    PartitionCell cell;
    cell.bounds = leaf.box;
    cell.size = octree.lattice.unit() * octree.lattice.step(leaf.depth);
    cell.level = leaf.depth;
    cell.reason = leaf.reason;
    const auto index = static_cast<std::uint32_t>(p.cells.size());
    for (const Loop& loop : leaf.loops) {
      CellLoop l;
      l.corners = loop.corners;
      for (const FaceId& id : loop.side_faces) {
        const auto f = static_cast<std::uint32_t>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
        l.side_faces.push_back(f);
        add_cell(p.faces[f], index);
      }
      cell.loops.push_back(std::move(l));
    }
    p.cells.push_back(std::move(cell));
  }
  return p;
}

OctreePartitioner::OctreePartitioner(const Surface& surface, const Box& box, PartitionSettings settings)
    : surface_(surface), box_(box), settings_(std::move(settings)) {
  settings_.adaptive = true;
}

CellPartition OctreePartitioner::build() {
  last_ = build_partition(surface_, box_, settings_, memo_);
  return cell_partition_of(last_);
}

bool OctreePartitioner::start_finer() {
  if (settings_.surface_depth >= settings_.max_depth) return false;
  ++settings_.surface_depth;
  settings_.force_split.clear();
  return true;
}

void OctreePartitioner::split(std::span<const std::size_t> cells) {
  for (const std::size_t c : cells) {
    if (c >= last_.leaves.size()) throw Error(ErrorKind::Internal, "octree: split of an unknown cell");
    settings_.force_split.push_back(CellKey{last_.leaves[c].depth, last_.leaves[c].coords});
  }
}

// Such a face stays ambiguous at every depth, since finer faces lie in the same plane, yet it holds one
// sheet whose cut is decided within kGrazingDistance of the cell: not two sheets closer than the cell.
// Sheets that close have a sign change of f between them, where grad f turns, and fail the normal
// condition. Evaluates f and grad f at the corners and centre of the ambiguous faces only.
bool OctreePartitioner::only_grazes_ambiguous_faces(std::size_t cell, const Sampler& f) const {
  const Leaf& leaf = last_.leaves.at(cell);
  const double side = leaf.box.size().maxCoeff();
  bool ambiguous = false;
  for (int face = 0; face < 6; ++face) {
    if (!face_ambiguous(leaf.config, face)) continue;
    ambiguous = true;
    const auto axis = static_cast<std::size_t>(cube::kFaceAxis[static_cast<std::size_t>(face)]);
    const auto grazes = [&](const Vec3& p) {
      const ValueGradient vg = f.value_gradient(p);
      const double g = vg.gradient.norm();
      return g > 0.0 && std::abs(vg.value) <= kGrazingDistance * side * g &&
             std::abs(vg.gradient[static_cast<Eigen::Index>(axis)]) >= kGrazingNormal * g;
    };
    Vec3 centre = Vec3::Zero();
    for (const int corner : cube::kFace[static_cast<std::size_t>(face)]) {
      const auto& offset = cube::kCorner[static_cast<std::size_t>(corner)];
      const Vec3 p = leaf.box.lo + Vec3(offset[0], offset[1], offset[2]).cwiseProduct(leaf.box.size());
      if (!grazes(p)) return false;
      centre += 0.25 * p;
    }
    if (!grazes(centre)) return false;
  }
  return ambiguous;
}

}  // namespace isopatch
