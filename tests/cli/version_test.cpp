// The version: the generated <isopatch/version.hpp> holds project(VERSION) of the top CMakeLists.txt,
// and `isopatch --version` prints it.
#include <isopatch/version.hpp>

#include <gtest/gtest.h>

#include <string>

#include "run_command.hpp"

namespace isopatch {
namespace {

TEST(Version, HeaderHoldsTheProjectVersion) {
  EXPECT_EQ(kVersion, ISOPATCH_PROJECT_VERSION);  // the project() line, passed by CMake
  EXPECT_EQ(std::string(kVersion), std::to_string(kVersionMajor) + "." + std::to_string(kVersionMinor) + "." +
                                       std::to_string(kVersionPatch));
  static_assert(kVersionMajor >= 0 && kVersionMinor >= 0 && kVersionPatch >= 0);
}

TEST(Version, CliPrintsTheVersionFromTheHeader) {
  const auto dir = test::scratch_dir("cli_version");
  const auto r = test::run_command(std::string(ISOPATCH_CLI) + " --version", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "isopatch " + std::string(kVersion) + "\n");
  EXPECT_NE(r.out.find(kVersion), std::string::npos) << r.out;
}

}  // namespace
}  // namespace isopatch
