#pragma once
// Layout checks of a .vdb file before OpenVDB reads it. OpenVDB allocates (and fills) what a file
// declares, a name of 2 GB for instance, before it reads the bytes: a corrupt or hostile file of a few
// bytes could take gigabytes. Every length and offset of the file's header, metadata, grid list and each
// grid's metadata and transform name is checked here against the bytes there are. A stream (a file
// written without a table of grid offsets) has its first grid's checked, the others' are not (only
// reading the first grid's tree tells where the next one starts).

#include <string>
#include <string_view>

namespace isopatch::vdb {

/// \pre `bytes` start with OpenVDB's magic number.
/// \throw IoError("<name>: the file is corrupt or truncated (...)") for a length or offset beyond the
///        file (or beyond its grid), or a file format older than OpenVDB 3 (version 222).
void prescan_vdb(std::string_view bytes, const std::string& name);

}  // namespace isopatch::vdb
