// OpenVDB's reading in a child process (vdb/isolated_read.hpp): the child's processor time and wall
// clock are bounded, and what it throws comes back of the same kind.
#include <gtest/gtest.h>
#include <isopatch/error.hpp>

#include <unistd.h>

#include <string>

#include "vdb/isolated_read.hpp"

namespace isopatch::vdb {
namespace {

std::string refusal(int cpu_seconds, const std::function<SparseSamples(std::string&)>& read) {
  std::string chosen;
  try {
    read_in_child("child.vdb", cpu_seconds, chosen, read);
  } catch (const IoError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(IsolatedRead, StopsAChildThatComputesPastItsProcessorTime) {
  const std::string message = refusal(1, [](std::string&) -> SparseSamples {
    volatile std::uint64_t n = 0;
    for (;;) n = n + 1;
  });
  EXPECT_NE(message.find("child.vdb: the file is corrupt: OpenVDB did not finish reading it in 1 s of "
                         "processor time"),
            std::string::npos)
      << message;
}

TEST(IsolatedRead, StopsAChildThatWaitsPastTheWallClock) {
  const std::string message = refusal(1, [](std::string&) -> SparseSamples {
    for (;;) ::pause();
  });
  EXPECT_NE(message.find("did not finish reading it in 4 s"), std::string::npos) << message;
  EXPECT_EQ(message.find("processor"), std::string::npos) << message;
}

TEST(IsolatedRead, ReturnsTheChildsSamplesAndItsErrorsOfTheSameKind) {
  std::string chosen;
  const SparseSamples s = read_in_child("child.vdb", 1, chosen, [](std::string& grid) {
    grid = "density";
    SparseSamples out;
    out.spacing = Vec3(0.5, 0.25, 2.0);
    out.active_voxels = 7;
    return out;
  });
  EXPECT_EQ(chosen, "density");
  EXPECT_EQ(s.spacing[1], 0.25);
  EXPECT_EQ(s.active_voxels, 7u);
  EXPECT_THROW(read_in_child("child.vdb", 1, chosen,
                             [](std::string&) -> SparseSamples { throw InputError("no grid 'x'", "grid"); }),
               InputError);
}

TEST(IsolatedRead, GivesLargerFilesMoreTime) {
  EXPECT_EQ(reading_seconds(0), 2);
  EXPECT_EQ(reading_seconds(1'000'000), 12);
  EXPECT_LT(reading_seconds(100'000), reading_seconds(10'000'000));
}

}  // namespace
}  // namespace isopatch::vdb
