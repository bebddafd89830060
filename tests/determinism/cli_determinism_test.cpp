// The tool is deterministic: the same command line run three times (three processes, with --threads
// 1, 2 and 4) writes the same file, byte for byte, for each mesher configuration (projection with the whole
// clean-up on two surfaces, the paper's method alone, the Coons base, --max-error, marching cubes) and each
// output format. The files must be non-empty and hold a closed mesh of the catalogue genus with more than 100
// vertices, so two equally empty or broken outputs do not pass.
#include <isopatch/catalogue.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kCli = ISOPATCH_CLI;

/// One mesher configuration: a catalogue surface and the options of `isopatch mesh` (each run well
/// under a second).
struct CliConfig {
  const char* name;  ///< part of the test name: letters, digits and '_'
  const char* surface;
  const char* options;
};

constexpr CliConfig kConfigs[] = {
    {"torus_projection", "torus", "--edge-length 0.1"},  // the default method, whole clean-up
    {"blobby_projection", "blobby", "--edge-length 0.08"},
    {"genus2_remesh0", "genus2", "--edge-length 0.05 --remesh 0"},  // the paper's method alone
    {"genus2_coons", "genus2", "--edge-length 0.05 --base coons"},
    {"tanglecube_preview", "tanglecube", "--quality preview"},
    {"torus_fine", "torus", "--edge-length 0.15 --quality fine"},
    {"blobby_max_error", "blobby", "--max-error 3e-3"},
    {"torus_mc", "torus", "--method mc --grid 48"},
};

constexpr const char* kFormats[] = {"ply", "obj", "off", "stl"};

struct CliCase {
  CliConfig config;
  std::string format;  ///< the output file's extension
};

std::vector<CliCase> cli_cases() {
  std::vector<CliCase> cases;
  for (const CliConfig& config : kConfigs)
    for (const char* format : kFormats) cases.push_back({config, format});
  return cases;
}

/// The test name: configuration and format.
std::string case_id(const CliCase& c) {
  return std::string(c.config.name) + "_" + c.format;
}

void PrintTo(const CliCase& c, std::ostream* out) {
  *out << "mesh " << c.config.surface << " " << c.config.options << " -q -o mesh." << c.format;
}

std::string case_name(const ::testing::TestParamInfo<CliCase>& info) {
  return case_id(info.param);
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

class CliDeterminism : public ::testing::TestWithParam<CliCase> {};

TEST_P(CliDeterminism, RunsWithOneTwoAndFourThreadsWriteTheSameBytes) {
  const CliCase& c = GetParam();
  // Per process, so that another build's copy of this test running at the same time keeps its own files.
  const auto dir = test::scratch_dir("determinism_" + case_id(c) + "_" + std::to_string(getpid()));
  constexpr int kThreads[] = {1, 2, 4};
  std::filesystem::path outputs[3];
  std::string bytes[3];
  for (int run = 0; run < 3; ++run) {
    // Same file name, separate folders: the command lines differ only in the folder and the threads.
    const auto run_dir = dir / ("run" + std::to_string(run));
    std::filesystem::create_directories(run_dir);
    outputs[run] = run_dir / ("mesh." + c.format);
    const auto r =
        test::run_command(kCli + " mesh " + c.config.surface + " " + c.config.options + " --threads " +
                              std::to_string(kThreads[run]) + " -q -o " + outputs[run].string(),
                          run_dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    bytes[run] = read_bytes(outputs[run]);
    ASSERT_FALSE(bytes[run].empty()) << outputs[run];
  }
  for (int run = 1; run < 3; ++run) {
    SCOPED_TRACE("1 thread against " + std::to_string(kThreads[run]));
    EXPECT_EQ(bytes[0].size(), bytes[run].size());
    const auto [first, second] =
        std::mismatch(bytes[0].begin(), bytes[0].end(), bytes[run].begin(), bytes[run].end());
    EXPECT_TRUE(first == bytes[0].end() && second == bytes[run].end())
        << "the outputs differ first at byte " << (first - bytes[0].begin()) << " of " << bytes[0].size();
  }

  // Not two equally empty or broken files: a closed mesh of the surface's genus.
  const Mesh mesh = read_mesh(outputs[0].string());
  EXPECT_GT(mesh.vertex_count(), 100u);
  EXPECT_GT(mesh.triangle_count(), 200u);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight()) << t.boundary_edges << " boundary edges";
  EXPECT_TRUE(t.manifold());
  EXPECT_EQ(t.genus, find_in_catalogue(c.config.surface)->genus);
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Configurations, CliDeterminism, ::testing::ValuesIn(cli_cases()), case_name);

}  // namespace
}  // namespace isopatch
