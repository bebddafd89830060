/// \file composite_patch.cpp
/// One composite patch as a job of the projection core (composite_patch.hpp).
#include "composite_mesher/composite_patch.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <memory>

#include "ngon/base_surface.hpp"
#include "ngon/patch_template.hpp"
#include "projection/fan_centre.hpp"

namespace isopatch {

namespace {

void check_patch(const CompositePatch& patch) {
  const std::size_t n = patch.sides.size();
  if (n < 3 || n > 12)
    throw InputError("patch '" + patch.name + "' has " + std::to_string(n) + " sides (want 3 to 12)");
  if (patch.corner_directions.size() != n)
    throw InputError("patch '" + patch.name + "' has " + std::to_string(patch.corner_directions.size()) +
                     " corner directions for " + std::to_string(n) + " sides");
}

/// The diagonal of the box of the boundary samples: the longest march is half of it.
double boundary_diameter(const PatchBoundary& boundary) {
  Vec3 lo = boundary.points[0][0], hi = lo;
  for (const auto& side : boundary.points)
    for (const Vec3& p : side) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  return (hi - lo).norm();
}

/// A unit direction to compare against grad f at a boundary vertex: the unit gradient of the patch's
/// function there, else (0/0 at an I-patch corner) `fallback`.
Vec3 boundary_normal(const Sampler& f, const Vec3& p, const Vec3& fallback) {
  const ValueGradient vg = f.value_gradient_unchecked(p);
  const double g = vg.gradient.norm();
  if (vg.gradient.allFinite() && g > 0.0) return vg.gradient / g;
  return fallback;
}

}  // namespace

PatchPiece project_composite_patch(const Sampler& f, const CompositePatch& patch,
                                   const PatchBoundary& boundary, const CompositePatchParams& params) {
  check_patch(patch);
  const int n = static_cast<int>(patch.sides.size());
  int r = 1;
  for (const auto& side : boundary.points) r = std::max(r, static_cast<int>(side.size()) - 1);
  const auto tmpl = patch_template(n, r, params.coordinates);
  BaseInputs inputs;
  for (const auto& side : boundary.points) inputs.corners.push_back(side.front());
  if (needs_side_curves(params.base)) inputs.side_curves = boundary.dense;
  const std::unique_ptr<BaseSurface> base = make_base_surface(params.base, std::move(inputs));
  const CurvedBounds bounds(patch.bounds, params.region_tolerance);
  const MarchRegion region = MarchRegion::curved_region(bounds, 0.5 * boundary_diameter(boundary));
  std::vector<std::uint32_t> ids(tmpl->vertex_count(), 0);
  std::vector<SurfacePoint> points(tmpl->vertex_count());
  for (std::size_t v = 0; v < tmpl->vertex_count(); ++v) {
    const VertexTag& tag = tmpl->tag(static_cast<int>(v));
    if (tag.kind == VertexTag::Kind::Interior) continue;
    const std::span<const double> lambda = tmpl->lambda(static_cast<int>(v));
    Vec3 d = Vec3::Zero();
    for (int k = 0; k < n; ++k)
      d += lambda[static_cast<std::size_t>(k)] * patch.corner_directions[static_cast<std::size_t>(k)];
    const auto k = static_cast<std::size_t>(tag.side);
    std::size_t i = 0;
    if (tag.kind == VertexTag::Kind::Side) {
      const auto count = static_cast<int>(boundary.points[k].size()) - 1;
      i = static_cast<std::size_t>((2 * tag.index * count + r) / (2 * r));
    }
    ids[v] = boundary.ids[k][i];
    points[v] = {boundary.points[k][i], boundary_normal(f, boundary.points[k][i], d.normalized())};
  }
  PatchStats stats;
  PatchPiece piece;
  piece.verdict =
      project_patch(f, *tmpl, *base, patch.corner_directions, region, params.projection, points, stats);
  piece.gradient_rays = stats.gradient_rays;
  if (piece.verdict != PatchVerdict::Accepted) return piece;
  for (std::size_t v = 0; v < tmpl->vertex_count(); ++v) {
    if (tmpl->tag(static_cast<int>(v)).kind != VertexTag::Kind::Interior) continue;
    ids[v] = PatchPiece::kLocalVertex + static_cast<std::uint32_t>(piece.points.size());
    piece.points.push_back(points[v].position);
  }
  for (const TemplateTriangle& t : tmpl->triangles()) {
    const auto a = static_cast<std::size_t>(t[0]), b = static_cast<std::size_t>(t[1]),
               c = static_cast<std::size_t>(t[2]);
    if (ids[a] == ids[b] || ids[b] == ids[c] || ids[c] == ids[a]) continue;  // merged on a short side
    piece.triangles.push_back({ids[a], ids[b], ids[c]});
  }
  return piece;
}

PatchPiece fan_patch(const Sampler& f, const CompositePatch& patch, const PatchBoundary& boundary,
                     const CompositePatchParams& params) {
  check_patch(patch);
  std::vector<std::uint32_t> polygon;
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < boundary.points.size(); ++k)
    for (std::size_t i = 0; i + 1 < boundary.points[k].size(); ++i) {
      polygon.push_back(boundary.ids[k][i]);
      points.push_back(boundary.points[k][i]);
    }
  Vec3 d = Vec3::Zero();
  for (const Vec3& n : patch.corner_directions) d += n;
  const CurvedBounds bounds(patch.bounds, params.region_tolerance);
  const MarchRegion region = MarchRegion::curved_region(bounds, 0.5 * boundary_diameter(boundary));
  const FanCentre centre = fan_centre(f, points, d, region, params.projection.march_steps);
  PatchPiece piece;
  piece.points.push_back(centre.point.position);
  if (!centre.projected) piece.unprojected = 1;
  for (std::size_t k = 0; k < polygon.size(); ++k)
    piece.triangles.push_back({PatchPiece::kLocalVertex, polygon[k], polygon[(k + 1) % polygon.size()]});
  return piece;
}

}  // namespace isopatch
