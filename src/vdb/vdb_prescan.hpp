#pragma once
// Layout checks of a .vdb file before OpenVDB reads it. OpenVDB allocates (and fills) what a file
// declares, a name of 2 GB for instance, before it reads the bytes: a corrupt or hostile file of a few
// bytes could take gigabytes; it reads as many root-node entries as a file declares, a billion from a
// stream that already failed. Every length and offset of the file's header, metadata, grid list and each
// grid's metadata and transform name, and the root node's counts of a float or double grid with an
// axis-aligned transform, is checked here against the bytes there are. A stream (a file
// written without grid offsets) may hold one grid only: the next grid's name would follow wherever a
// corrupt first grid made its reader stop.

#include <string>
#include <string_view>

namespace isopatch::vdb {

/// \pre `bytes` start with OpenVDB's magic number.
/// \throw IoError("<name>: the file is corrupt or truncated (...)") for a length, offset or count beyond
///        the file (or beyond its grid), a file format older than OpenVDB 3 (version 222), or a stream of
///        more than one grid.
void prescan_vdb(std::string_view bytes, const std::string& name);

}  // namespace isopatch::vdb
