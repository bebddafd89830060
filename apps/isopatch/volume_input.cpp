// A volume file as the surface of `isopatch mesh` (volume_input.hpp).
#include "volume_input.hpp"

#include <isopatch/error.hpp>
#include <isopatch/vdb_surface.hpp>
#include <isopatch/volume_io.hpp>
#include <isopatch/volume_surface.hpp>

#include <charconv>
#include <cmath>
#include <vector>

namespace isopatch::cli {

namespace {

/// "a,b,c" or "a" (all three) as finite numbers. \throw SettingError naming `setting`.
Vec3 parse_triple(const std::string& text, const std::string& setting) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    double v = 0.0;
    const char* b = text.data() + start;
    const char* e = text.data() + end;
    if (b != e && *b == '+') ++b;
    const auto [ptr, ec] = std::from_chars(b, e, v);
    if (b == e || ec != std::errc() || ptr != e || !std::isfinite(v))
      throw SettingError(setting, "bad " + setting + " '" + text + "': want three finite numbers a,b,c");
    values.push_back(v);
    start = end + 1;
  }
  if (values.size() == 1) return Vec3::Constant(values[0]);
  if (values.size() != 3)
    throw SettingError(setting, "bad " + setting + " '" + text + "': want three finite numbers a,b,c");
  return Vec3(values[0], values[1], values[2]);
}

}  // namespace

SurfacePtr volume_input(const std::string& path, const VolumeOptions& options) {
  Volume volume = read_volume(path);
  if (!options.spacing.empty()) volume.spacing = parse_triple(options.spacing, "spacing");
  if (!options.origin.empty()) volume.origin = parse_triple(options.origin, "origin");
  const std::size_t slash = path.find_last_of('/');
  return volume_surface(std::move(volume), options.level.value_or(0.0),
                        slash == std::string::npos ? path : path.substr(slash + 1));
}

SurfacePtr vdb_input(const std::string& path, const VolumeOptions& options, const std::string& grid) {
  if (!options.spacing.empty() || !options.origin.empty())
    throw InputError(
        "--spacing and --origin are for .npy and .nrrd volumes: a .vdb grid's transform gives them");
  VdbSource source;
  source.grid = grid;
  source.level = options.level.value_or(0.0);
  return vdb_surface(path, source);
}

int marching_cubes_cells(const std::optional<std::string>& grid, const std::optional<int>& mc_grid,
                         bool vdb) {
  if (mc_grid) return *mc_grid;
  if (!grid || vdb) return 64;
  int cells = 0;
  const char* end = grid->data() + grid->size();
  const auto [ptr, ec] = std::from_chars(grid->data(), end, cells);
  if (grid->empty() || ec != std::errc() || ptr != end)
    throw SettingError("grid", "bad --grid '" + *grid +
                                   "': want a whole number of cells (a grid's name is for .vdb inputs)");
  return cells;
}

}  // namespace isopatch::cli
