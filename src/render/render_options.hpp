#pragma once
// What render_mesh and field_vertex_colours share about RenderOptions: the option checks and the
// values and range of the field modes.

#include <isopatch/mesh.hpp>
#include <isopatch/render.hpp>

#include <vector>

namespace isopatch::render {

inline bool is_field_mode(RenderMode mode) {
  return mode == RenderMode::ScalarField || mode == RenderMode::Error;
}

/// \throw InputError for any option out of the range render.hpp documents for render_mesh.
void check_options(const RenderOptions& options);

/// The field modes' values: options.values when not empty, else the attribute options.field.
/// \throw InputError when there are none or their count is not the vertex count.
std::vector<double> field_values(const Mesh& mesh, const RenderOptions& options);

/// The colour map's half-width m: options.range, else the robust magnitude at options.percentile
/// (falling back to the largest |value|, then to 1 when every value is 0 or undefined).
double colour_range(const std::vector<double>& values, const RenderOptions& options);

}  // namespace isopatch::render
