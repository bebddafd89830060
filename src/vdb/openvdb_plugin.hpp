#pragma once
// The part of the .vdb reader that uses OpenVDB, built as its own shared object (isopatch_openvdb.so)
// and loaded only when a .vdb file is read (openvdb_loader.hpp): linking Debian's libopenvdb into every
// program cost each start-up about 35 ms of symbol relocations (69,000 of them), most of what
// `isopatch --version` took. The functions of the table throw isopatch's errors (IoError, InputError) as
// the rest of the reader does: the plugin is built with the library, by the same compiler.

#include <isopatch/vdb_surface.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "vdb/sparse_samples.hpp"

namespace isopatch::vdb {

/// What the plugin offers, as one table of functions.
struct OpenVdbFunctions {
  int version;  ///< kOpenVdbPluginVersion of the build that made the plugin
  /// Registers OpenVDB's grid types (openvdb::initialize); called once, before any other function.
  void (*initialize)();
  /// The samples of grid `grid` (empty: the one vdb_surface.hpp picks) of the file whose bytes are
  /// `bytes` (the pre-scan passed them), its name in `grid_name`; `offsets`: read as a file, each grid
  /// from its offsets, else as a stream. Runs in the reading child (isolated_read.hpp): the grid stays
  /// alive until the child leaves. \throw IoError, InputError (setting "grid").
  SparseSamples (*read_samples)(std::string_view bytes, bool offsets, const std::string& grid,
                                const std::string& name, std::string& grid_name);
  /// The grids of the file at `path` (the pre-scan passed it). \throw IoError.
  std::vector<VdbGridInfo> (*list_grids)(const std::string& path);
};

/// Changed whenever OpenVdbFunctions or the types it passes change: a plugin of another build is refused.
inline constexpr int kOpenVdbPluginVersion = 1;

}  // namespace isopatch::vdb

/// The plugin's one exported symbol.
extern "C" __attribute__((visibility("default"))) const isopatch::vdb::OpenVdbFunctions*
isopatch_openvdb_functions();
