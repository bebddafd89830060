#pragma once
// Loading the OpenVDB plugin (openvdb_plugin.hpp) the first time a .vdb file is read.

#include "vdb/openvdb_plugin.hpp"

namespace isopatch::vdb {

/// The plugin's functions, its initialize() already called. Loads isopatch_openvdb.so on the first call
/// (thread-safe) from, in this order: $ISOPATCH_OPENVDB_PLUGIN (a path), the folder of the program or
/// Python module this code is in, that folder's ../<libdir>/isopatch/, the installed <libdir>/isopatch/,
/// and the build tree. In a build with OpenVDB linked in (ISOPATCH_OPENVDB_LINKED: the fuzzers) the
/// table is the linked one. \throw IoError naming the places looked in and the loader's message when no
/// plugin loads, or when the one found is of another build (kOpenVdbPluginVersion).
const OpenVdbFunctions& openvdb_functions();

}  // namespace isopatch::vdb
