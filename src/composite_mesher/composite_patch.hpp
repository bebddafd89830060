#pragma once
/// \file composite_patch.hpp
/// One patch of a composite as a job of the projection core (Sipos & Salvi 2021, sec. 2.2 and sec. 4):
/// the template triangulation of its n-gon domain (patch/patch_template.hpp), boundary vertices taken
/// from the shared samples of its curves, interior vertices placed on the base surface (the multi-sided
/// C0 Coons patch over the sides, Salvi 2020, or the barycentric combination of the corners) and
/// projected by projection/patch_projection.hpp onto the patch's own function along the interpolated
/// corner directions, inside the patch's region (curved bounds, project/march_region.hpp). The
/// fallback fan is project/fan_centre.hpp's.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "composite_model/composite.hpp"
#include "ngon/barycentric.hpp"
#include "projection/patch_projection.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// The shared boundary of one patch: side k runs from corner k to corner k + 1.
struct PatchBoundary {
  std::vector<std::vector<Vec3>> points;        ///< per side, its samples (segments + 1, both corners)
  std::vector<std::vector<std::uint32_t>> ids;  ///< per side, the mesh ids of those samples
  std::vector<std::vector<Vec3>> dense;         ///< per side, a dense polyline of its curve (Coons base)
};

/// How the composite's patches are projected.
struct CompositePatchParams {
  ProjectionParams projection;  ///< march steps and the acceptance angle (its resolution is not read)
  CoordinateKind coordinates = CoordinateKind::Wachspress;
  /// The base (not Automatic): Coons over the sides' dense polylines, or Barycentric over the corners.
  PatchSettings::Base base = PatchSettings::Base::Coons;
  double region_tolerance = 0.0;  ///< how far outside a bound an interior vertex may lie
};

/// What a patch adds to the mesh: new vertices and triangles whose ids are mesh ids of the boundary
/// (below kLocalVertex) or kLocalVertex + the index of a new vertex.
struct PatchPiece {
  static constexpr std::uint32_t kLocalVertex = 0x80000000u;
  PatchVerdict verdict = PatchVerdict::Accepted;
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::size_t gradient_rays = 0;  ///< interior vertices for which a ray along grad f was tried
  std::size_t unprojected = 0;    ///< fan centres no ray brought onto f = 0 (fan_patch only)
};

/// Meshes the patch at the template resolution r = the largest segment count of its sides; a side
/// with fewer segments c gives template vertex i the sample round(i c / r), and the triangles that
/// collapse are dropped. On any verdict but Accepted, `points` and `triangles` are empty.
/// \pre boundary has patch.sides.size() sides, consecutive sides share their corner ids.
/// \throw InputError when the patch has fewer than 3 or more than 12 sides, or its corner directions
///        do not match its sides; EvaluationError when f or a bound is not finite where evaluated.
PatchPiece project_composite_patch(const Sampler& f, const CompositePatch& patch,
                                   const PatchBoundary& boundary, const CompositePatchParams& params);

/// The fallback for a patch still rejected after refinement: its boundary polygon fanned around one
/// centre (fan_centre.hpp) marched from the polygon's centroid along the mean corner direction, else
/// grad f, inside the region; counted in `unprojected` when no ray finds f = 0.
/// \throw as project_composite_patch.
PatchPiece fan_patch(const Sampler& f, const CompositePatch& patch, const PatchBoundary& boundary,
                     const CompositePatchParams& params);

}  // namespace isopatch
