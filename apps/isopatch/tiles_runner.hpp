#pragma once
// `isopatch mesh SURFACE --tiles N --out-dir DIR [--scheduler local|tcp://HOST:PORT] [-o FILE]`: the
// blocked run on Dask (docs/distributed.md) is the Python package's isopatch.distributed; the tool
// hands it the surface and the settings that apply and becomes that process (its exit codes are the
// tool's own).

#include <optional>
#include <string>
#include <vector>

namespace isopatch::cli {

struct TilesOptions {
  int tiles = 0;  ///< 0: not a blocked run
  std::string out_dir;
  std::string scheduler = "local";
  int workers = 2;
  std::string memory_limit;
  int prefilter_window = 0;      ///< a volume's prefilter windows (samples per side); 0: the driver's own
  std::string split = "blocks";  ///< "blocks" of one base, or "planes": tiles of the box by planes
};

/// What a blocked run is given from `isopatch mesh`'s own options.
struct TilesJob {
  std::string surface;
  std::string output;
  std::string box;
  std::vector<std::string> params;
  std::optional<double> level;
  std::optional<double> edge_length;
  std::string quality;
  int refine = 0;
  std::string creases;
};

/// Replaces the process with `python3 -m isopatch.distributed` for `job` and `tiles` (the interpreter
/// the package was built for; the build tree's package first on its path when it exists). Returns only
/// on failure. \throw InputError when tiles < 1 or out_dir is empty; IoError when Python cannot be run.
[[noreturn]] void run_tiles(const TilesOptions& tiles, const TilesJob& job);

}  // namespace isopatch::cli
