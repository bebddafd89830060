// The projection mesher over convex partitions (convex_meshing.hpp).
#include "project/convex_meshing.hpp"

#include <isopatch/error.hpp>
#include <isopatch/projection.hpp>

#include <chrono>
#include <string>

#include "partition/convex_partitioner.hpp"
#include "partition/octree_partitioner.hpp"
#include "project/cell_sizing.hpp"
#include "project/refining_mesher.hpp"

namespace isopatch {
namespace {

/// The bounds of region ∩ `box`, or an error naming `setting`: `what` is empty in the box, or reaches
/// the box when `must_be_inside` (the box then stands for infinity).
Box bounds_within(const std::vector<CellPlane>& planes, const Box& box, const char* setting,
                  const std::string& what, bool must_be_inside) {
  ConvexCell cell;
  try {
    cell = intersect_half_spaces(box, planes, must_be_inside ? 0.0 : 1e-12);
  } catch (const InputError&) {
    throw SettingError(setting, what + (must_be_inside ? " is empty" : " does not meet the box"));
  }
  if (must_be_inside)
    for (const ConvexCell::Face& face : cell.faces())
      if (cell.planes()[face.plane].label < 0)
        throw SettingError(setting, what + " is unbounded: give a box as well");
  return cell.bounds();
}

Box grown(const Box& b) {
  const Vec3 margin = Vec3::Constant(1e-3 * b.diagonal());
  return Box{b.lo - margin, b.hi + margin};
}

}  // namespace

std::vector<CellPlane> cell_planes(const ConvexRegion& region) {
  std::vector<CellPlane> planes;
  for (std::size_t i = 0; i < region.size(); ++i) {
    const HalfSpace& h = region[i];
    planes.push_back(make_cell_plane(h.a, h.b, h.c, h.d, static_cast<std::int64_t>(i)));
  }
  return planes;
}

std::optional<Box> convex_meshing_box(const Surface& surface, const Settings& settings) {
  if (settings.region.empty() && settings.cells.empty()) return std::nullopt;
  const bool given = settings.box.has_value();
  // Without a box, "unbounded" is judged within 10^4 times the surface's box.
  const Box far{surface.box().centre() - 1e4 * surface.box().size(),
                surface.box().centre() + 1e4 * surface.box().size()};
  const Box within = given ? valid_box(*settings.box) : far;
  if (!settings.region.empty()) {
    const Box b = bounds_within(cell_planes(settings.region), within, "region", "the region", !given);
    return given ? within : grown(b);
  }
  Box all{Vec3::Constant(std::numeric_limits<double>::infinity()),
          Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (std::size_t i = 0; i < settings.cells.size(); ++i) {
    const Box b =
        bounds_within(cell_planes(settings.cells[i]), within, "cells", "cell " + std::to_string(i), !given);
    all.lo = all.lo.cwiseMin(b.lo);
    all.hi = all.hi.cwiseMax(b.hi);
  }
  return given ? within : grown(all);
}

Mesh mesh_convex(const Surface& surface, const Settings& settings, const Box& box, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  settings.SizeSettings::validate();
  settings.OctreeSettings::validate();
  settings.PatchSettings::validate();
  settings.ProjectionSettings::validate();
  settings.BudgetSettings::validate();
  const double edge = default_edge_length(settings, box);
  ConvexPartitionerSettings s;
  s.cancel = settings.cancel;
  if (!settings.region.empty()) {
    // The octree's depths for this box: the region's cells are its cubes, clipped.
    OctreeDepthRequest request;
    request.closest = settings.resolution > 0;
    request.cell_length = edge * (settings.resolution > 0 ? settings.resolution : kAutoSegments);
    request.min_depth = settings.min_depth;
    request.max_depth = settings.max_depth;
    request.raise_limit_by = settings.resolution != 0 ? -1 : settings.refinement_levels;
    const OctreeDepths depths = plan_octree_depths(box, request);
    s.start_level = depths.start;
    s.max_level = depths.limit;
  } else {
    s.start_level = 0;
    s.max_level = std::min(kMaxPartitionLevel, settings.refinement_levels + 4);
  }
  const CellMesherSettings stages{settings, settings, settings};
  const TargetSizes sizes = target_sizes(settings, box);
  Mesh mesh;
  if (!settings.region.empty()) {
    ConvexPartitioner partitioner =
        ConvexPartitioner::clipped_lattice(surface, box, cell_planes(settings.region), s);
    mesh = mesh_refining(surface, partitioner, settings, stages, sizes, stats);
  } else {
    std::vector<std::vector<CellPlane>> cells;
    for (const ConvexRegion& c : settings.cells) cells.push_back(cell_planes(c));
    try {
      ConvexPartitioner partitioner = ConvexPartitioner::given_cells(surface, box, cells, s);
      mesh = mesh_refining(surface, partitioner, settings, stages, sizes, stats);
    } catch (const SettingError&) {
      throw;
    } catch (const InputError& e) {
      throw SettingError("cells", e.what());
    }
  }
  if (stats) stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return mesh;
}

}  // namespace isopatch
