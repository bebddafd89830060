// Warnings of `isopatch mesh` (see mesh_warnings.hpp).
#include "mesh_warnings.hpp"

#include <string>

namespace isopatch::cli {
namespace {

double extra(const MeshStats& stats, const std::string& name) {
  const auto it = stats.extra.find(name);
  return it == stats.extra.end() ? 0.0 : it->second;
}

}  // namespace

void print_mesh_warnings(const MeshStats& stats, std::FILE* out) {
  if (const double doubtful = extra(stats, "doubtful_cells"); doubtful > 0)
    std::fprintf(out,
                 "warning: %g cells at the depth limit %g (side %.3g) still hold two sheets of f = 0 or an "
                 "ambiguous face: sheets closer than that may be joined or dropped there (a larger "
                 "--max-depth looks finer)\n",
                 doubtful, extra(stats, "max_depth"), extra(stats, "doubtful_cell_size"));
  if (const double beyond = extra(stats, "error_bound_violations"); beyond > 0)
    std::fprintf(out, "warning: %g triangles have their centroid farther than --max-error from f = 0\n",
                 beyond);
}

}  // namespace isopatch::cli
