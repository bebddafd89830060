// The region and the box of convex partitions (convex_meshing.hpp).
#include "projection/convex_meshing.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

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

std::optional<Box> region_bounds(const ConvexRegion& region, const Box& far) {
  validate_region(region, "region");
  if (region.empty()) return std::nullopt;
  ConvexCell cell;
  try {
    cell = intersect_half_spaces(valid_box(far), cell_planes(region), 0.0);
  } catch (const InputError&) {
    throw SettingError("region", "the region is empty");
  }
  for (const ConvexCell::Face& face : cell.faces())
    if (cell.planes()[face.plane].label < 0) return std::nullopt;
  return grown(cell.bounds());
}

std::optional<Box> region_bounds(const ConvexRegion& region) {
  // Within 10^4 times the planes' largest distance from the origin (at least 1).
  double reach = 1.0;
  for (const HalfSpace& h : region) {
    const double n = Vec3(h.a, h.b, h.c).stableNorm();
    if (n > 0.0 && std::isfinite(h.d)) reach = std::max(reach, std::abs(h.d) / n);
  }
  const Vec3 r = Vec3::Constant(1e4 * reach);
  return region_bounds(region, Box{-r, r});
}

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
    if (given) {
      bounds_within(cell_planes(settings.region), within, "region", "the region", false);
      return within;
    }
    // A bounded region stands instead of the box; an unbounded one lies inside the surface's own box.
    if (const std::optional<Box> b = region_bounds(settings.region, far)) return *b;
    bounds_within(cell_planes(settings.region), valid_box(surface.box()), "region", "the region", false);
    return valid_box(surface.box());
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

}  // namespace isopatch
