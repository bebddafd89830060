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
/// axis. \throw InputError for a bad grid or box; EvaluationError if f is NaN/inf at a grid point;
/// NoSurfaceError if no grid edge is crossed; LimitError on cancel or max_vertices.
Mesh marching_cubes(const Surface& surface, const Settings& settings, MeshStats* stats = nullptr);

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
