#pragma once
/// \file dual_contouring.hpp
/// Plain Dual Contouring (Ju, Losasso, Schaefer & Warren, "Dual contouring of Hermite data",
/// SIGGRAPH 2002) on a uniform grid, a peer for meshes of CSG shapes with creases: f sampled at the
/// cell corners, Hermite data (crossing point, unit normal) on every edge whose ends differ in sign,
/// one vertex per cell with such an edge at the minimiser of its QEF (qef.hpp) clamped to the cell,
/// one quad (two triangles) per such edge joining the four cells around it. Benchmark code only; this
/// is the method as libfive-like tools ship it, without the paper's octree simplification and without
/// any manifold or self-intersection repair (its output may self-intersect).

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <cstddef>

namespace isopatch::bench {

struct DualContouringOptions {
  int cells = 32;           ///< cells along the longest side of the box; the cells are cubes
  int crossing_steps = 8;   ///< false-position steps (Illinois) locating f = 0 on an edge
  double truncation = 0.1;  ///< QEF singular values below this times the largest are taken as zero
};

/// The mesh and what it took (wall times, seconds).
struct DualContouringResult {
  Mesh mesh;                             ///< triangles counter-clockwise seen from outside (f > 0)
  int cells = 0;                         ///< options.cells of this mesh
  std::array<int, 3> grid{};             ///< cells per axis
  double spacing = 0.0;                  ///< side of a cell
  std::size_t value_evaluations = 0;     ///< evaluations of f: grid corners and crossing search
  std::size_t gradient_evaluations = 0;  ///< one per sign-changing edge
  std::size_t non_finite_values = 0;     ///< NaN or infinite values of f (taken as positive, outside)
  std::size_t clamped_vertices = 0;      ///< vertices whose QEF minimiser left the cell
  std::size_t boundary_edges = 0;        ///< sign-changing edges without four cells (no quad)
  double seconds = 0.0;                  ///< this run: sampling to Mesh
  int search_runs = 1;                   ///< runs of the resolution search (vertex_target.hpp)
  double search_seconds = 0.0;           ///< all of them (this run's seconds without a search)
};

/// Dual Contouring of f = 0 in `box`: a grid anchored at box.lo, options.cells cubic cells along the
/// longest side, reaching at least box.hi on the others. Single-threaded, so the output is the same
/// bytes on every run. \throw InputError for an invalid box or options; whatever evaluating f throws
DualContouringResult dual_contouring(const Surface& surface, const Box& box,
                                     const DualContouringOptions& options);

}  // namespace isopatch::bench
