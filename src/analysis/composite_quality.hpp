#pragma once
/// \file composite_quality.hpp
/// Measures of a composite's projection mesh that need to know the patches: element quality inside the
/// patches, the distance of every vertex from its own patch's function, and the jump of the normal
/// across patch seams against the jump inside patches (isophotes are continuous across a seam when
/// the two patches meet with G1 continuity, Sipos & Salvi 2021, sec. 4; Varady et al. 2001).

#include <cstddef>

#include "composite_model/composite.hpp"
#include "composite_model/composite_mesh_parts.hpp"

namespace isopatch {

struct CompositeQuality {
  std::size_t patch_vertices = 0;  ///< vertices inside patches (not on a curve)
  double patch_valence_6 = 0.0;    ///< share of them with valence 6
  double patch_min_angle = 0.0;    ///< smallest angle of a triangle with no vertex on a curve, degrees
  double min_angle = 0.0;          ///< smallest angle of any triangle, degrees
  /// Largest |f| / |grad f| of a vertex's own patch function (every patch at a curve vertex) over the
  /// box diagonal.
  double max_relative_distance = 0.0;
  std::size_t seam_edges = 0;   ///< edges between triangles of two patches
  std::size_t patch_edges = 0;  ///< edges between triangles of one patch
  /// Mean angle between the normals of the two triangles at an edge, over the edge's length, in
  /// degrees per unit length (a discrete normal curvature): across seams and inside patches.
  double seam_normal_jump = 0.0;
  double patch_normal_jump = 0.0;
  /// The worst seam: over every pair of neighbouring patches, the mean jump across their seam over the
  /// mean jump at the patch edges beside it (the other edges of the two triangles at each seam edge;
  /// at least 1 degree over the box diagonal, so that flat patches meeting in a plane compare). About 1
  /// where the patches meet with G1 continuity at the mesh's scale; a crease, or a turn within a band
  /// narrower than an edge, gives far more.
  double worst_seam_ratio = 0.0;
  /// The same ratio with every triangle's normal replaced by its patch's gradient at the triangle's
  /// centroid: how fast the surface itself turns across its seams, seen at the mesh's scale. A surface
  /// that turns within a band narrower than an edge beside a seam shows it here too.
  double surface_seam_ratio = 0.0;
  /// Largest angle between the gradients of the two patches meeting at a curve sample (corners left
  /// out, where I-patch functions are 0/0), degrees: 0 for G1 patches.
  double seam_gradient_angle = 0.0;
};

/// \pre `m` is mesh_composite_projection(composite, ...) or refine_composite(composite, ...).
/// \throw EvaluationError when a patch function is not finite at a vertex.
CompositeQuality measure_composite_mesh(const Composite& composite, const CompositeMesh& m);

}  // namespace isopatch
