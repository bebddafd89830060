// .vdb files into SparseSamples (vdb_reader.hpp): the file's bytes, its magic number and layout checked
// (vdb_prescan.hpp), then the trees read by the OpenVDB plugin (openvdb_loader.hpp) in a child process
// (isolated_read.hpp).
#include "vdb/vdb_reader.hpp"

#include "vdb/isolated_read.hpp"
#include "vdb/openvdb_loader.hpp"
#include "vdb/vdb_prescan.hpp"

#include <isopatch/error.hpp>
#include <isopatch/volume.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>

namespace isopatch::vdb {

namespace {

/// OpenVDB's magic number, the file's first 8 bytes (little-endian): "VDB " then zeros.
constexpr std::uint64_t kMagic = 0x56444220;

void check_magic(std::string_view head, const std::string& name) {
  std::uint64_t magic = 0;
  if (head.size() >= sizeof magic) std::memcpy(&magic, head.data(), sizeof magic);
  if (magic != kMagic) throw IoError(name + ": not an OpenVDB file (no 'VDB' magic number at its start)");
}

/// Whether the file's grid list has offsets (the byte after its magic number, versions and library
/// version), as OpenVDB's file writer makes it; a stream's has none. \pre the pre-scan passed.
bool has_grid_offsets(std::string_view bytes) {
  return bytes.size() > 20 && bytes[20] != 0;
}

/// The bytes of the file at `path`, checked for the magic number. \throw IoError.
std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw IoError(path + ": cannot open the file");
  const std::streamoff size = in.tellg();
  if (!in || size < 0) throw IoError(path + ": cannot read the file");
  if (static_cast<std::uint64_t>(size) > kMaxVolumeSamples * sizeof(double))
    throw IoError(path + ": the file is larger than " + std::to_string(kMaxVolumeSamples * sizeof(double)) +
                  " bytes");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(bytes.data(), size)) throw IoError(path + ": cannot read the file");
  check_magic(bytes, path);
  return bytes;
}

}  // namespace

SparseSamples read_grid(const std::string& path, const std::string& grid, std::string& chosen) {
  // Read whole: the pre-scan checks every grid's offsets against the file's size (OpenVDB's own reader
  // does not notice a file cut inside its last leaves), and the child reads these very bytes.
  return decode_grid(file_bytes(path), grid, path, chosen);
}

SparseSamples decode_grid(std::string_view bytes, const std::string& grid, const std::string& name,
                          std::string& chosen) {
  check_magic(bytes, name);
  prescan_vdb(bytes, name);
  const OpenVdbFunctions& openvdb = openvdb_functions();  // loaded here, before the child is forked
  // The trees are read in a child process (isolated_read.hpp): OpenVDB overflows a node's buffer on
  // some corrupt chunks. A file with grid offsets (what OpenVDB's file writer makes) is read as a file,
  // each grid from the offsets the pre-scan checked (a stream reader would take whatever follows a
  // corrupt grid for the next grid's name); a stream (one grid, the pre-scan sees to it) as a stream.
  const bool offsets = has_grid_offsets(bytes);
  return read_in_child(name, reading_seconds(bytes.size()), chosen, [&](std::string& grid_name) {
    return openvdb.read_samples(bytes, offsets, grid, name, grid_name);
  });
}

std::vector<VdbGridInfo> list_grids(const std::string& path) {
  prescan_vdb(file_bytes(path), path);
  return openvdb_functions().list_grids(path);
}

}  // namespace isopatch::vdb
