#pragma once
// Reading .vdb files into SparseSamples, with Debian's OpenVDB (libopenvdb-dev) in a plugin
// (openvdb_plugin.hpp): grid choice, value types, transforms and every refusal of vdb_surface.hpp.

#include <isopatch/vdb_surface.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "vdb/sparse_samples.hpp"

namespace isopatch::vdb {

/// The samples of the grid `grid` (empty: the one grid vdb_surface.hpp picks) of the file at `path`,
/// and the grid's name in `chosen`. \throw IoError, InputError (setting "grid") as vdb_surface.hpp.
SparseSamples read_grid(const std::string& path, const std::string& grid, std::string& chosen);
/// The same from the bytes of a file; `name` stands for it in messages.
SparseSamples decode_grid(std::string_view bytes, const std::string& grid, const std::string& name,
                          std::string& chosen);
/// The grids of the file at `path`. \throw IoError.
std::vector<VdbGridInfo> list_grids(const std::string& path);

}  // namespace isopatch::vdb
