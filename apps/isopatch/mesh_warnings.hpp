#pragma once
// Warnings of `isopatch mesh`: what the mesh written may get wrong, read from the mesher's statistics.

#include <isopatch/isopatch.hpp>

#include <cstdio>

namespace isopatch::cli {

/// Prints one "warning: ..." line on `out` for each doubt the statistics record: cells left in doubt
/// at the depth limit (doubtful_cells: sheets closer than a cell may be joined or dropped there) and
/// triangles beyond the --max-error bound (error_bound_violations). Prints nothing for a clean run.
void print_mesh_warnings(const MeshStats& stats, std::FILE* out);

}  // namespace isopatch::cli
