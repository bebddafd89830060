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

/// Meshes surface.box() (or settings.box) on a grid of settings.grid cubic cells along the longest
/// axis, whose outer planes are the box faces (see marching_cubes_grid()): f is evaluated only in the
/// closed box, and every vertex lies in it. One z-slab of cells at a time: two layers of samples are kept,
/// so working memory is O(N^2). Vertices sit on the crossed grid edges, one per edge, placed by
/// settings.edge_root; with EdgeRoot::Bracketed they lie on f = 0 to ~1e-13 of a cell.
/// settings.progress is called and settings.cancel checked once per slab. `stats` (optional)
/// receives the time, the number of f evaluations (grid and root finding) and the output size.
/// \throw SettingError for a bad grid, offset or box (naming the field); EvaluationError if f is NaN/inf
/// where evaluated; NoSurfaceError if no grid edge is crossed; LimitError on cancel or max_vertices.
Mesh marching_cubes(const Surface& surface, const Settings& settings, MeshStats* stats = nullptr);

/// The lattice marching_cubes() samples: point (i, j, k) is (planes[0][i], planes[1][j], planes[2][k])
/// for 0 <= i <= cells[0], 0 <= j <= cells[1], 0 <= k <= cells[2]. Every point lies in the closed box.
struct McGrid {
  /// Lattice plane coordinates per axis, increasing; the first is box.lo, the last box.hi.
  std::array<std::vector<double>, 3> planes;
  double cell = 0.0;           ///< edge length of the inner (cubic) cells
  std::array<int, 3> cells{};  ///< cells along x, y, z: planes[a].size() - 1

  /// Lattice point (i, j, k). \pre the indices are in range.
  Vec3 point(int i, int j, int k) const {
    return Vec3(planes[0][static_cast<std::size_t>(i)], planes[1][static_cast<std::size_t>(j)],
                planes[2][static_cast<std::size_t>(k)]);
  }
};

/// The grid for `box`: cell = longest box side / settings.grid. The outer lattice planes are the box
/// faces, so f is evaluated only in the closed box and every vertex lies in it. The inner planes along
/// axis a are box.lo[a] + (m - sigma[a]) * cell for the integers m with cell / 2 <= (m - sigma[a]) *
/// cell < box side - cell / 2, where sigma = settings.grid_offset * (0.1234, 0.5678, 0.9012) shifts them
/// off dyadic positions. Inner cells are cubes of side `cell`; the outermost layer on each side is
/// between cell / 2 and 3 cell / 2 thick. The longest axis has exactly settings.grid cells. With offset
/// 0 the inner planes are box.lo + m * cell (the outer layers are full cells when the side is a multiple
/// of cell).
/// \throw SettingError unless 1 <= settings.grid <= 4096, 0 <= settings.grid_offset < 1, box.valid().
McGrid marching_cubes_grid(const Box& box, const MarchingCubesSettings& settings);

/// One case of the generated table: triangles as triples of cube-edge indices, in the cube numbering
/// the octree partition uses too (docs/algorithms.md 2.3).
/// Cube corners: 0:(0,0,0) 1:(1,0,0) 2:(1,1,0) 3:(0,1,0) 4:(0,0,1) 5:(1,0,1) 6:(1,1,1) 7:(0,1,1).
/// Edges: (0,1)(1,2)(2,3)(3,0)(4,5)(5,6)(6,7)(7,4)(1,5)(6,2)(0,4)(7,3).
/// Bit i of a case index is set when corner i is negative.
struct McCase {
  std::vector<std::array<int, 3>> triangles;
};

/// The 256 generated cases (built once, thread-safe).
const std::array<McCase, 256>& marching_cubes_table();

}  // namespace isopatch
