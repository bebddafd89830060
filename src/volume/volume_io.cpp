// Volume files by extension (volume_io.hpp); the formats are in npy_reader.cpp and nrrd_reader.cpp.
#include <isopatch/error.hpp>
#include <isopatch/volume_io.hpp>

#include <algorithm>
#include <cctype>

#include "mesh/io_util.hpp"
#include "volume/npy_reader.hpp"
#include "volume/nrrd_reader.hpp"

namespace isopatch {

namespace {

bool ends_with_ci(const std::string& path, std::string_view suffix) {
  if (path.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), path.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(b)) == a; });
}

}  // namespace

bool is_volume_path(const std::string& path) {
  return ends_with_ci(path, ".npy") || ends_with_ci(path, ".nrrd");
}

VolumeFormat volume_format_from_path(const std::string& path) {
  if (ends_with_ci(path, ".npy")) return VolumeFormat::Npy;
  if (ends_with_ci(path, ".nrrd")) return VolumeFormat::Nrrd;
  throw IoError(path + ": unknown volume format (want .npy or .nrrd)");
}

Volume read_volume(const std::string& path) {
  const VolumeFormat format = volume_format_from_path(path);
  return decode_volume(io::load_file(path), format, path);
}

Volume decode_volume(std::string_view bytes, VolumeFormat format, const std::string& name) {
  Volume v =
      format == VolumeFormat::Npy ? volume_io::decode_npy(bytes, name) : volume_io::decode_nrrd(bytes, name);
  try {
    v.validate();
  } catch (const InputError& e) {
    throw IoError(name + ": " + e.what());
  }
  return v;
}

}  // namespace isopatch
