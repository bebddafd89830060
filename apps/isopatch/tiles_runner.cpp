// The blocked run handed to isopatch.distributed (tiles_runner.hpp).
#include "tiles_runner.hpp"

#include <isopatch/error.hpp>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace isopatch::cli {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

}  // namespace

void run_tiles(const TilesOptions& tiles, const TilesJob& job) {
  if (tiles.tiles < 1) throw InputError("--tiles must be at least 1", "tiles");
  if (tiles.out_dir.empty())
    throw InputError("--tiles needs --out-dir (where the blocks and the manifest go)", "tiles");
  std::vector<std::string> args{ISOPATCH_PYTHON, "-m", "isopatch.distributed"};
  // FLAG=VALUE, so that values starting with '-' (a box, a formula) are not read as flags.
  const auto add = [&](const char* flag, const std::string& value) {
    if (!value.empty()) args.push_back(std::string(flag) + "=" + value);
  };
  add("--tiles", std::to_string(tiles.tiles));
  add("--out-dir", tiles.out_dir);
  add("--scheduler", tiles.scheduler);
  add("--workers", std::to_string(tiles.workers));
  add("--memory-limit", tiles.memory_limit);
  if (tiles.prefilter_window != 0) add("--prefilter-window", std::to_string(tiles.prefilter_window));
  if (tiles.split != "blocks") add("--split", tiles.split);
  add("--output", job.output);
  add("--box", job.box);
  for (const std::string& p : job.params) add("--param", p);
  if (job.level) add("--level", number(*job.level));
  if (job.edge_length) add("--edge-length", number(*job.edge_length));
  add("--quality", job.quality);
  if (job.refine != 0) add("--refine", std::to_string(job.refine));
  add("--creases", job.creases);
  args.emplace_back("--");
  args.push_back(job.surface);
  // The build tree's package, when this tool runs from the build tree it was built in.
  const std::filesystem::path build_package = ISOPATCH_BUILD_PYTHONPATH;
  if (std::filesystem::exists(build_package / "isopatch" / "distributed.py")) {
    std::string path = build_package.string();
    if (const char* old = std::getenv("PYTHONPATH"); old && *old) path += std::string(":") + old;
    setenv("PYTHONPATH", path.c_str(), 1);
  }
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(argv[0], argv.data());
  throw IoError(std::string("cannot run ") + ISOPATCH_PYTHON + " for --tiles: " + std::strerror(errno));
}

}  // namespace isopatch::cli
