#pragma once
/// \file metrics.hpp
/// Quality and accuracy of a triangle mesh of an implicit surface, as defined in docs/algorithms.md
/// section 7 ("Measuring the result"): element shape, valence of interior vertices,
/// and, given the surface, distance to f = 0, normal errors and curvature errors against the exact
/// values (curvature.hpp).

#include <isopatch/mesh.hpp>
#include <isopatch/self_intersection.hpp>
#include <isopatch/surface.hpp>
#include <isopatch/topology.hpp>

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace isopatch {

/// Summary of a sample. Percentiles interpolate linearly between order statistics (p-th percentile
/// at rank p/100 (n - 1)). All fields are NaN for an empty sample; infinities are kept (mean = inf).
struct Distribution {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::size_t count = 0;
  double min = kNaN, p1 = kNaN, p5 = kNaN, median = kNaN, p95 = kNaN, p99 = kNaN, max = kNaN;
  double mean = kNaN, rms = kNaN;  ///< arithmetic mean and root mean square
};

/// Summarizes `samples` (any order). \throw InputError if a sample is NaN.
Distribution summarize(std::vector<double> samples);

/// Element shape, over all triangles. Angles in degrees; a zero-area triangle has smallest angle 0,
/// aspect ratio +inf and quality 0.
struct ShapeReport {
  Distribution min_angle;       ///< smallest angle of each triangle
  double share_below_10 = 0.0;  ///< fraction of triangles (0..1) whose smallest angle is < 10 degrees
  double share_below_20 = 0.0;
  double share_below_30 = 0.0;
  Distribution aspect_ratio;    ///< R / (2 r), 1 for equilateral
  Distribution quality;         ///< Frey-Borouchaki Q = (6 / sqrt 3) A / (p l_max), in [0, 1]
  Distribution edge_length;     ///< over distinct undirected edges
  double edge_length_cv = 0.0;  ///< coefficient of variation std / mean of the edge lengths
};

/// Valence (number of distinct neighbours) of interior vertices: referenced vertices all of whose
/// edges are shared by exactly two triangles (so boundary vertices are left out).
struct ValenceReport {
  std::size_t interior_vertices = 0;
  std::size_t other_vertices = 0;      ///< referenced but on a boundary or non-manifold edge
  std::vector<std::size_t> histogram;  ///< histogram[k] = interior vertices of valence k
  double share_6 = 0.0;                ///< fraction of interior vertices of valence 6
  double share_5_to_7 = 0.0;
};

/// Discrete against exact curvature over the interior vertices where both are finite.
struct CurvatureError {
  std::size_t vertices = 0;   ///< interior vertices compared
  std::size_t undefined = 0;  ///< interior vertices left out: a value was not finite
  double nrms =
      0.0;  ///< ||d - a||_2 / ||a||_2 (sums over vertices; NaN if nothing compared, inf if all a = 0)
  Distribution abs_error;  ///< |d - a|
};

/// Accuracy against the surface (f's exact derivatives as ground truth).
struct AccuracyReport {
  double diagonal = 0.0;               ///< bounding-box diagonal of the mesh (divide distances by it)
  Distribution vertex_distance;        ///< d1 = |f| / |grad f| at the vertices
  Distribution centroid_distance;      ///< d1 at the triangle centroids (chordal error)
  Distribution triangle_normal_error;  ///< degrees between triangle normal and grad f at centroid
  Distribution vertex_normal_error;    ///< degrees, area-weighted vertex normal against grad f
  /// Samples left out of the four distributions above: f or grad f not finite, grad f = 0, or a
  /// zero normal (zero-area triangle, unreferenced vertex).
  std::size_t undefined_samples = 0;
  CurvatureError mean_curvature;      ///< H_d against H ("H nRMS")
  CurvatureError gaussian_curvature;  ///< K_d against K
};

struct QualityReport {
  TopologyReport topology;
  SelfIntersectionReport self_intersections;  ///< find_self_intersections(mesh), up to 1000 pairs
  ShapeReport shape;
  ValenceReport valence;
  std::optional<AccuracyReport> accuracy;  ///< present when a surface was given
};

/// Measures `mesh` (and its accuracy against `surface` when not null). O(V + F log F) plus one
/// second-order evaluation of f per vertex and one first-order evaluation per triangle.
/// \throw InputError for an index out of range or a non-finite position (as analyze_topology).
QualityReport analyze_quality(const Mesh& mesh, const Surface* surface = nullptr);

/// The parts of analyze_quality, each on its own (same preconditions and errors).
ShapeReport analyze_shape(const Mesh& mesh);
ValenceReport analyze_valence(const Mesh& mesh);
AccuracyReport analyze_accuracy(const Mesh& mesh, const Surface& surface);

/// Triangles with an angle under some limit, and the smallest angle of all.
struct SmallAngleCount {
  std::size_t triangles = 0;  ///< with their smallest angle under the limit
  double smallest = 180.0;    ///< degrees, over every triangle (180 for a mesh without triangles)
};
/// Counts the triangles of `mesh` whose smallest angle is under `degrees`: analyze_shape's min-angle
/// figures in one pass and no memory beyond the mesh (for meshes of millions of triangles).
/// \throw InputError as analyze_shape.
SmallAngleCount count_small_angles(const Mesh& mesh, double degrees);

/// Element shape and valence away from given points: the figures that matter for the rest of a mesh
/// of a surface with singular points (singular_points.hpp), near which no element shape is promised.
struct ShapeAwayReport {
  double radius = 0.0;                ///< of the balls left out
  std::size_t centres = 0;            ///< balls left out
  std::size_t triangles = 0;          ///< triangles with no vertex in a ball (measured)
  std::size_t triangles_near = 0;     ///< triangles with a vertex in a ball (left out)
  double smallest_angle = 180.0;      ///< degrees, over the measured triangles (180 when there is none)
  double share_below_20 = 0.0;        ///< fraction of the measured triangles with an angle under 20 degrees
  std::size_t interior_vertices = 0;  ///< interior vertices (as ValenceReport) outside every ball
  double share_6 = 0.0;               ///< fraction of those of valence 6 (valence in the whole mesh)
};
/// Measures the triangles of `mesh` none of whose vertices lies in a closed ball of `radius` about a
/// point of `centres`, and the interior vertices outside every ball (their valence counted in the whole
/// mesh), with analyze_shape's smallest angle and analyze_valence's interior vertices. With no centre,
/// every triangle and interior vertex is measured. O(V + F log F), the centres hashed into cubes of
/// side `radius` (samples along a curve of singular points at a spacing under `radius` leave out a tube).
/// \throw InputError as analyze_shape, and for a radius that is not a positive number or a centre that
/// is not finite.
ShapeAwayReport analyze_shape_away(const Mesh& mesh, std::span<const Vec3> centres, double radius);

}  // namespace isopatch
