#pragma once
/// \file settings.hpp
/// One Settings struct for every mesher, each field with its documented default, and the statistics
/// a mesher reports back.

#include <isopatch/geometry.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace isopatch {

enum class Method {
  Projection,     ///< the paper's method (default)
  MarchingCubes,  ///< Lorensen & Cline 1987 baseline
};

/// How marching cubes places a vertex on a crossed grid edge.
enum class EdgeRoot {
  Bracketed,  ///< a bracketed root finder (Illinois / bisection safeguard) to ~1e-13 of the edge: on f = 0
  Linear,     ///< linear interpolation of the two end values, as in the original algorithm
};

/// Progress of a long run, reported through Settings::progress.
struct Progress {
  std::size_t done = 0;   ///< work units done (e.g. grid slabs, cells)
  std::size_t total = 0;  ///< work units in all
};

struct Settings {
  Method method = Method::Projection;
  /// The region to mesh; the surface's default box when empty. Must be valid().
  std::optional<Box> box;

  // --- Marching cubes ---------------------------------------------------------------------------
  /// Cells along the longest box axis; cells are cubes and the grid covers the whole box. 1..4096.
  int grid = 64;
  EdgeRoot edge_root = EdgeRoot::Bracketed;
  /// The grid origin is shifted by this fraction of a cell along the non-dyadic direction
  /// (0.1234, 0.5678, 0.9012) so symmetric surfaces do not pass through grid points. 0 disables.
  double grid_offset = 1e-3;

  // --- Budgets and control ----------------------------------------------------------------------
  /// Abort with LimitError when the output would exceed this many vertices. 0: no limit.
  std::size_t max_vertices = 0;
  /// Called now and then from the meshing thread; may be empty.
  std::function<void(const Progress&)> progress;
  /// When set and true, the mesher stops with LimitError("cancelled") at the next check.
  const std::atomic<bool>* cancel = nullptr;
};

/// What a mesher did, for summaries and benchmarks.
struct MeshStats {
  double seconds = 0.0;
  std::uint64_t value_evaluations = 0;     ///< evaluations of f alone
  std::uint64_t gradient_evaluations = 0;  ///< evaluations of f with its gradient
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::map<std::string, double> extra;  ///< method-specific counters, printed by name
};

}  // namespace isopatch
