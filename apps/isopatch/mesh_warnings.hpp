#pragma once
// Warnings of `isopatch mesh`: what the mesh written may get wrong, from the mesher's statistics and a
// self-intersection test of the mesh.

#include <isopatch/isopatch.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/self_intersection.hpp>

#include <cstdio>

namespace isopatch::cli {

/// Prints one "warning: ..." line on `out` for each doubt: cells left in doubt at the depth limit
/// (MeshWarnings::doubtful_topology_cells: sheets closer than a cell may be joined or dropped there),
/// triangles beyond the --max-error bound (MeshWarnings::error_bound_violations), triangles with an
/// angle under 10 degrees after a clean-up (MeshStats::cleanup: marching cubes alone makes such slivers by
/// design; not with cells in doubt, whose warning covers them), and pairs of triangles of `mesh` that
/// intersect (`crossings`: find_self_intersections of `mesh`, up to 1000 pairs, made by the caller, which
/// times it). Prints nothing for a clean run.
void print_mesh_warnings(const MeshStats& stats, const Mesh& mesh, const SelfIntersectionReport& crossings,
                         std::FILE* out);

}  // namespace isopatch::cli
