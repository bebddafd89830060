#pragma once
/// \file csg_composite.hpp
/// A CSG shape (a formula built with min, max and abs) as a composite surface (composite.hpp): its
/// faces cut into disc-like pieces, each piece a patch on its face's own function inside the face's
/// region, bounded by the creases and seams the pieces share, so the composite mesher (Sipos & Salvi
/// 2021, sec. 4: curves known, sampled once, patches projected onto their own functions) meshes the
/// shape with its creases and corners exact. docs/creases.md describes the whole method.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "composite_model/composite.hpp"
#include "csg/crease_search.hpp"
#include "csg/face_set.hpp"

namespace isopatch {

/// What the analysis found and the composite built from it.
struct CsgShape {
  Composite composite;
  std::size_t faces = 0;         ///< faces (after merging the sides of smooth blends)
  std::size_t creases = 0;       ///< crease curves as traced (before splits)
  std::size_t corners = 0;       ///< nodes where three or more faces meet
  std::size_t seams = 0;         ///< seam curves cutting faces into pieces
  std::size_t smooth_pairs = 0;  ///< pairs of faces merged because they meet without a crease
  /// Corners of pieces whose angle is below the triangle angle floor: triangles there cannot reach it.
  std::size_t exempt_corners = 0;
  /// What the interval cover certified: where two faces may meet and what explained each place.
  CreaseCertificate certificate;
  std::vector<SurfacePtr> face_functions;  ///< the function of every face that has pieces
  /// The faces as the analysis left them (merged where they meet smoothly): which face a point of the
  /// shape belongs to, for measures and tests (not thread-safe while it meets new faces).
  std::shared_ptr<FaceSet> face_set;
};

/// Analyses `surface` in `box` for creases with a seed grid of about `cell`. nullopt when the surface
/// is not a formula, has no min, max or abs, or has no crease in the box (its switches are all smooth
/// there), or when a crease leaves the box (then `leaves_box`, when given, is set to where): such a
/// surface is meshed as a smooth one.
/// \throw CreaseError for a shape that cannot be meshed with its creases (see crease_search.hpp and
///        face_regions.hpp); EvaluationError, NoSurfaceError.
std::optional<CsgShape> analyse_csg(const Surface& surface, const Box& box, double cell,
                                    std::optional<Vec3>* leaves_box = nullptr);

/// The angle floor (degrees) below which a piece's corner is counted as exempt.
inline constexpr double kExemptCornerDegrees = 25.0;

}  // namespace isopatch
