#pragma once
/// \file compare.hpp
/// Side-by-side comparison of the meshers on one surface at matched vertex counts, as in the paper's
/// evaluation (Sipos & Salvi 2021, sec. 3 and Figures 1, 2): Marching Cubes, Marching Cubes followed by
/// Laplace fairing, and projection, measured with the metrics of metrics.hpp.

#include <isopatch/composite_mesh.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <string>
#include <vector>

namespace isopatch {

struct ComparisonRow {
  std::string method;  ///< "mc", "mc+fair" or "projection"
  int level = 0;       ///< density level, 0 = coarsest
  std::size_t vertices = 0;
  double seconds = 0.0;
  std::uint64_t evaluations = 0;  ///< evaluations of f plus evaluations of f with its gradient
  double valence6 = 0.0;          ///< share of interior vertices of valence 6, 0..1
  double min_angle = 0.0;         ///< degrees
  double share_below_20 = 0.0;    ///< share of triangles with smallest angle under 20 degrees, 0..1
  double normal_error = 0.0;      ///< mean angle between vertex normal and grad f, degrees
  double h_nrms = 0.0;            ///< normalized RMS error of the discrete mean curvature
  Mesh mesh;                      ///< the mesh itself (for pictures)
};

struct ComparisonSettings {
  /// Target edge lengths of the projection meshes, one per density level; empty: the longest box side
  /// divided by 24, 40 and 64.
  std::vector<double> edge_lengths;
  int fair_iterations = 10;  ///< rounds of Laplace fairing for the "mc+fair" rows
  Settings base;             ///< box, resolution and other mesher settings shared by all rows
};

/// For every level: projection at the level's edge length, then Marching Cubes with the grid whose
/// vertex count comes closest to the projection mesh's, then the same MC mesh faired.
/// \throw whatever the meshers throw (InputError, EvaluationError, NoSurfaceError, LimitError).
std::vector<ComparisonRow> compare_methods(const Surface& surface, const ComparisonSettings& settings);

/// The same for a composite surface: projection by mesh_composite() (its known curves, sampled once),
/// Marching Cubes and fairing on the composite as one piecewise surface, all measured against it.
/// \throw as mesh_composite() and mesh_surface().
std::vector<ComparisonRow> compare_methods(const CompositeModel& model, const ComparisonSettings& settings);

}  // namespace isopatch
