#pragma once
/// \file marching_cubes.hpp
/// Marching Cubes (Lorensen & Cline, SIGGRAPH 1987), the baseline the paper compares against.
/// The 256-case table is generated at start-up from the rule "separate the negative corners from the
/// positive ones" (no pasted table); every grid-edge crossing is computed once and shared, so the
/// mesh is watertight where the surface is closed inside the box, manifold, and oriented with normals
/// along grad f (f < 0 inside, f >= 0 counts as positive).

#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <vector>

namespace isopatch {

/// Meshes surface.box() (or settings.box) on a cubic grid of settings.grid cells along the longest
/// axis (see marching_cubes_grid()). One z-slab of cells at a time: two layers of samples are kept,
/// so working memory is O(N^2). Vertices sit on the crossed grid edges, one per edge, placed by
/// settings.edge_root; with EdgeRoot::Bracketed they lie on f = 0 to ~1e-13 of a cell.
/// settings.progress is called and settings.cancel checked once per slab. `stats` (optional)
/// receives the time, the number of f evaluations (grid and root finding) and the output size.
/// \throw InputError for a bad grid, offset or box; EvaluationError if f is NaN/inf where evaluated;
/// NoSurfaceError if no grid edge is crossed; LimitError on cancel or max_vertices.
Mesh marching_cubes(const Surface& surface, const Settings& settings, MeshStats* stats = nullptr);

/// The lattice marching_cubes() samples: point (i, j, k) is origin + cell * (i, j, k) for
/// 0 <= i <= cells[0], 0 <= j <= cells[1], 0 <= k <= cells[2].
struct McGrid {
  Vec3 origin = Vec3::Zero();
  double cell = 0.0;           ///< edge length of the cubic cells
  std::array<int, 3> cells{};  ///< cells along x, y, z
};

/// The grid for `box`: cell = longest box side / settings.grid; the origin is box.lo shifted back by
/// settings.grid_offset * cell * (0.1234, 0.5678, 0.9012), and each axis has the fewest cells that
/// reach box.hi from there (up to 1e-9 of a cell), so with an offset the grid usually has one cell
/// more than the box along each axis and overhangs it by less than a cell.
/// \throw InputError unless 1 <= settings.grid <= 4096, 0 <= settings.grid_offset < 1, box.valid().
McGrid marching_cubes_grid(const Box& box, const Settings& settings);

/// One case of the generated table: triangles as triples of cube-edge indices.
/// Cube corners: 0:(0,0,0) 1:(1,0,0) 2:(1,1,0) 3:(0,1,0) 4:(0,0,1) 5:(1,0,1) 6:(1,1,1) 7:(0,1,1).
/// Edges: (0,1)(1,2)(2,3)(3,0)(4,5)(5,6)(6,7)(7,4)(0,4)(1,5)(2,6)(3,7).
/// Bit i of a case index is set when corner i is negative.
struct McCase {
  std::vector<std::array<int, 3>> triangles;
};

/// The 256 generated cases (built once, thread-safe).
const std::array<McCase, 256>& marching_cubes_table();

}  // namespace isopatch
