#pragma once
/// \file patch_projection.hpp
/// One patch of a composite meshed by projection (Sipos & Salvi 2021, sec. 2.2 and sec. 4): the
/// template triangulation of its n-gon domain (patch/patch_template.hpp), boundary vertices taken from
/// the shared samples of its curves, interior vertices placed on the multi-sided C0 Coons patch over
/// the sides (Salvi 2020; patch/coons_patch.hpp) and moved onto the patch's own function along
/// d(x) = sum_k lambda_k(x) N_k, the corner directions interpolated, within the patch's region
/// (patch_region.hpp), falling back to grad f at the base point. Then the paper's acceptance tests:
/// every ray meets f = 0 inside the region within the acceptance angle, and no triangle's normal
/// opposes the gradients at its corners.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ipatch/composite.hpp"
#include "patch/barycentric.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

/// The shared boundary of one patch: side k runs from corner k to corner k + 1.
struct PatchBoundary {
  std::vector<std::vector<Vec3>> points;        ///< per side, its samples (segments + 1, both corners)
  std::vector<std::vector<std::uint32_t>> ids;  ///< per side, the mesh ids of those samples
  std::vector<std::vector<Vec3>> dense;         ///< per side, a dense polyline of its curve (Coons base)
};

enum class PatchOutcome {
  Accepted,
  RayMissed,  ///< a ray found no crossing of f = 0 inside the region (neither d(x) nor grad f)
  RayAngle,   ///< every ray met f = 0 beyond the acceptance angle to grad f
  Flipped,    ///< a triangle's normal opposes the gradients at its vertices
};

struct PatchProjectionParams {
  CoordinateKind coordinates = CoordinateKind::Wachspress;
  int march_steps = 32;               ///< steps over the longest march (half the patch's diameter)
  double cos_max_ray_angle = 0.2588;  ///< cos of the acceptance angle between a ray and grad f
  double region_tolerance = 0.0;      ///< how far outside a bound an interior vertex may lie
};

/// What a patch adds to the mesh: new vertices and triangles whose ids are mesh ids of the boundary
/// (below kLocalVertex) or kLocalVertex + the index of a new vertex.
struct PatchPiece {
  static constexpr std::uint32_t kLocalVertex = 0x80000000u;
  PatchOutcome outcome = PatchOutcome::Accepted;
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::size_t gradient_rays = 0;  ///< interior vertices projected along grad f instead of d(x)
  std::size_t unprojected = 0;    ///< fan centres no ray brought onto f = 0 (fan_patch only)
};

/// Meshes the patch at the template resolution r = the largest segment count of its sides; a side
/// with fewer segments c gives template vertex i the sample round(i c / r), and the triangles that
/// collapse are dropped. On any outcome but Accepted, `points` and `triangles` are empty.
/// \pre boundary has patch.sides.size() sides, consecutive sides share their corner ids.
/// \throw InputError when the patch has fewer than 3 or more than 12 sides, or its corner directions
///        do not match its sides; EvaluationError when f or a bound is not finite where evaluated.
PatchPiece project_patch_on_region(const Sampler& f, const CompositePatch& patch,
                                   const PatchBoundary& boundary, const PatchProjectionParams& params);

/// The fallback for a patch still rejected after refinement: its boundary polygon fanned around one
/// centre vertex, marched onto f = 0 from the polygon's centroid (along the mean corner direction,
/// else grad f) inside the region; counted in `unprojected` when no ray finds it.
PatchPiece fan_patch(const Sampler& f, const CompositePatch& patch, const PatchBoundary& boundary,
                     const PatchProjectionParams& params);

}  // namespace isopatch
