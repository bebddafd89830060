/// \file patch_projection.cpp
/// Projection of one composite patch inside its region (patch_projection.hpp).
#include "composite/patch_projection.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include "composite/patch_region.hpp"
#include "patch/coons_patch.hpp"
#include "patch/patch_template.hpp"
#include "patch/polyline_curve.hpp"

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

/// The diagonal of the box of the boundary samples.
double boundary_diameter(const PatchBoundary& boundary) {
  Vec3 lo = boundary.points[0][0], hi = lo;
  for (const auto& side : boundary.points)
    for (const Vec3& p : side) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  return (hi - lo).norm();
}

/// The dense polylines of the sides (in the sides' directions) for the Coons base.
std::vector<PolylineCurve> coons_curves(const PatchBoundary& boundary) {
  std::vector<PolylineCurve> curves;
  for (const auto& side : boundary.dense) curves.emplace_back(side);
  return curves;
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

PatchPiece project_patch_on_region(const Sampler& f, const CompositePatch& patch,
                                   const PatchBoundary& boundary, const PatchProjectionParams& params) {
  check_patch(patch);
  const int n = static_cast<int>(patch.sides.size());
  int r = 1;
  for (const auto& side : boundary.points) r = std::max(r, static_cast<int>(side.size()) - 1);
  const auto tmpl = patch_template(n, r, params.coordinates);
  const CoonsPatch base(coons_curves(boundary));
  const PatchRegion region(patch, params.region_tolerance);
  const double reach = 0.5 * boundary_diameter(boundary);
  PatchPiece piece;
  std::vector<std::uint32_t> ids(tmpl->vertex_count(), 0);
  std::vector<Vec3> position(tmpl->vertex_count());
  std::vector<Vec3> normal(tmpl->vertex_count());  // unit gradient (or the corner direction)
  for (std::size_t v = 0; v < tmpl->vertex_count(); ++v) {
    const VertexTag& tag = tmpl->tag(static_cast<int>(v));
    const std::span<const double> lambda = tmpl->lambda(static_cast<int>(v));
    Vec3 d = Vec3::Zero();
    for (int k = 0; k < n; ++k)
      d += lambda[static_cast<std::size_t>(k)] * patch.corner_directions[static_cast<std::size_t>(k)];
    if (tag.kind != VertexTag::Kind::Interior) {
      const auto k = static_cast<std::size_t>(tag.side);
      std::size_t i = 0;
      if (tag.kind == VertexTag::Kind::Side) {
        const auto count = static_cast<int>(boundary.points[k].size()) - 1;
        i = static_cast<std::size_t>((2 * tag.index * count + r) / (2 * r));
      }
      ids[v] = boundary.ids[k][i];
      position[v] = boundary.points[k][i];
      normal[v] = boundary_normal(f, position[v], d.normalized());
      continue;
    }
    const Vec3 p = base.evaluate(lambda);
    const ValueGradient at_base = f.value_gradient(p);
    std::optional<RegionHit> hit;
    bool angle_failed = false;
    if (d.norm() > 1e-12) {
      hit = march_in_region(f, region, p, at_base.value, d, reach, params.march_steps);
      if (hit && std::abs(hit->direction.dot(hit->gradient.normalized())) < params.cos_max_ray_angle) {
        hit.reset();
        angle_failed = true;
      }
    }
    if (!hit && at_base.gradient.norm() > 0.0) {
      hit = march_in_region(f, region, p, at_base.value, at_base.gradient, reach, params.march_steps);
      if (hit && std::abs(hit->direction.dot(hit->gradient.normalized())) < params.cos_max_ray_angle) {
        hit.reset();
        angle_failed = true;
      }
      if (hit) ++piece.gradient_rays;
    }
    if (!hit) {
      piece.outcome = angle_failed ? PatchOutcome::RayAngle : PatchOutcome::RayMissed;
      return piece;
    }
    ids[v] = PatchPiece::kLocalVertex + static_cast<std::uint32_t>(piece.points.size());
    piece.points.push_back(hit->point);
    position[v] = hit->point;
    normal[v] = hit->gradient.normalized();
  }
  for (const TemplateTriangle& t : tmpl->triangles()) {
    const auto a = static_cast<std::size_t>(t[0]), b = static_cast<std::size_t>(t[1]),
               c = static_cast<std::size_t>(t[2]);
    if (ids[a] == ids[b] || ids[b] == ids[c] || ids[c] == ids[a]) continue;  // merged on a short side
    const Vec3 nt = (position[b] - position[a]).cross(position[c] - position[a]);
    if (!(nt.dot(normal[a] + normal[b] + normal[c]) > 0.0)) {
      piece = PatchPiece{};
      piece.outcome = PatchOutcome::Flipped;
      return piece;
    }
    piece.triangles.push_back({ids[a], ids[b], ids[c]});
  }
  return piece;
}

PatchPiece fan_patch(const Sampler& f, const CompositePatch& patch, const PatchBoundary& boundary,
                     const PatchProjectionParams& params) {
  check_patch(patch);
  std::vector<std::uint32_t> polygon;
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < boundary.points.size(); ++k)
    for (std::size_t i = 0; i + 1 < boundary.points[k].size(); ++i) {
      polygon.push_back(boundary.ids[k][i]);
      points.push_back(boundary.points[k][i]);
    }
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : points) centre += p;
  centre /= static_cast<double>(points.size());
  Vec3 d = Vec3::Zero();
  for (const Vec3& n : patch.corner_directions) d += n;
  const PatchRegion region(patch, params.region_tolerance);
  const double reach = 0.5 * boundary_diameter(boundary);
  const ValueGradient at = f.value_gradient(centre);
  std::optional<RegionHit> hit;
  if (d.norm() > 1e-12) hit = march_in_region(f, region, centre, at.value, d, reach, params.march_steps);
  if (!hit && at.gradient.norm() > 0.0)
    hit = march_in_region(f, region, centre, at.value, at.gradient, reach, params.march_steps);
  PatchPiece piece;
  piece.points.push_back(hit ? hit->point : centre);
  if (!hit) piece.unprojected = 1;
  for (std::size_t k = 0; k < polygon.size(); ++k)
    piece.triangles.push_back({PatchPiece::kLocalVertex, polygon[k], polygon[(k + 1) % polygon.size()]});
  return piece;
}

}  // namespace isopatch
