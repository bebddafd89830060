#pragma once
/// \file curvature.hpp
/// Mean and Gaussian curvature of an implicit surface, exact (from f's derivatives, declared in
/// level_set_curvature.hpp, which this header includes) and discrete (from a triangle mesh), and
/// per-vertex fields of both for storing beside the mesh.
///
/// Sign convention: with f < 0 inside and outward normals, a sphere of radius R has H = +1/R and
/// K = 1/R^2, both for the analytic and for the discrete values.

#include <isopatch/level_set_curvature.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <vector>

namespace isopatch {

/// Discrete curvature of a triangle mesh at every vertex (Meyer, Desbrun, Schroeder, Barr 2003,
/// "Discrete differential-geometry operators for triangulated 2-manifolds").
/// A vertex is *interior* when it belongs to a triangle and every edge at it is shared by exactly two
/// triangles (boundary and non-manifold vertices are not interior). Only interior vertices get values;
/// all other entries (and vertices next to a zero-area triangle, where cotangents are infinite) are NaN.
struct DiscreteCurvature {
  std::vector<double> mean;      ///< H_d = (K(x) . n) / 2, K(x) the cotangent mean-curvature normal
  std::vector<double> gaussian;  ///< K_d = (2 pi - sum of angles) / mixed area
  std::vector<double> area;      ///< mixed Voronoi area (defined for every referenced vertex)
  std::vector<bool> interior;    ///< see above
};

/// Computes DiscreteCurvature. n is the area-weighted vertex normal of the mesh's own orientation
/// (counter-clockwise seen from outside), so H_d > 0 on a convex outward-oriented mesh.
/// Sum over interior vertices of gaussian * area is the total angle deficit (2 pi chi on a closed mesh).
/// O(V + F log F). \throw InputError for an index out of range or a non-finite position.
DiscreteCurvature discrete_curvature(const Mesh& mesh);

/// Per-vertex fields of a mesh against its surface (NaN where undefined, as above).
struct CurvatureFields {
  std::vector<double> mean_discrete;   ///< H_d (interior vertices)
  std::vector<double> mean_analytic;   ///< H of the level set through the vertex
  std::vector<double> gauss_discrete;  ///< K_d (interior vertices)
  std::vector<double> gauss_analytic;  ///< K of the level set through the vertex
  std::vector<double> distance;        ///< signed first-order distance f / |grad f| (> 0 outside)
};

/// \throw InputError as discrete_curvature.
CurvatureFields curvature_fields(const Mesh& mesh, const Surface& surface);

/// Stores curvature_fields() as float vertex attributes (written by the PLY writer), replacing any
/// of the same names: mean_curvature (H_d), mean_curvature_exact (H), gaussian_curvature (K_d),
/// gaussian_curvature_exact (K), distance (f / |grad f|).
/// \throw InputError as discrete_curvature.
void attach_fields(Mesh& mesh, const Surface& surface);

}  // namespace isopatch
