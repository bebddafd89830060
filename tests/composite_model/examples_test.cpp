// Every examples/*.ipatch file parses into a closed composite whose curves lie on the functions of both
// patches that share them, with the two patches' gradients parallel there (G1 across every curve).
#include "composite_model/composite_checks.hpp"
#include "composite_model/ipatch_file.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>

namespace isopatch {
namespace {

std::vector<std::filesystem::path> example_files() {
  std::vector<std::filesystem::path> out;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(ISOPATCH_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() == ".ipatch") out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(IpatchExamples, ThereAreControlPolyhedraAndBlendedSolids) {
  // cube, octahedron, prism, pulled box; rounded box, square and pentagonal pyramids.
  EXPECT_GE(example_files().size(), 7u);
}

TEST(IpatchExamples, EveryExampleIsClosedAndItsCurvesLieOnBothPatches) {
  for (const auto& path : example_files()) {
    SCOPED_TRACE(path.filename().string());
    const auto start = std::chrono::steady_clock::now();
    const Composite c = read_ipatch(path.string());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NO_THROW(check_composite_closed(c));
    const double size = c.box.diagonal();
    // curve -> the patches (and side) that use it
    std::map<std::uint32_t, std::vector<std::size_t>> users;
    for (std::size_t p = 0; p < c.patches.size(); ++p) {
      EXPECT_LE(boundary_residual(c, p), 1e-9 * size) << c.patches[p].name;
      for (const PatchSide& s : c.patches[p].sides) users[s.curve].push_back(p);
    }
    double worst_angle = 0.0;
    for (const auto& [curve, patches] : users) {
      ASSERT_EQ(patches.size(), 2u);
      for (int j = 1; j < 16; ++j) {
        const Vec3 x = c.curves[curve].point(j / 16.0);
        const Vec3 g0 = c.patches[patches[0]].surface->value_gradient(x).gradient.normalized();
        const Vec3 g1 = c.patches[patches[1]].surface->value_gradient(x).gradient.normalized();
        worst_angle = std::max(worst_angle, std::atan2(g0.cross(g1).norm(), g0.dot(g1)));
      }
    }
    EXPECT_LT(worst_angle, 1e-7) << "largest angle between the two patches' normals on a shared curve";
    double residual = 0.0;
    for (std::size_t p = 0; p < c.patches.size(); ++p) residual = std::max(residual, boundary_residual(c, p));
    std::printf(
        "%-34s %3zu patches %3zu curves  max |f|/|grad f| on curves %.1e  max normal angle %.1e rad  %.3f "
        "s\n",
        path.filename().string().c_str(), c.patches.size(), c.curves.size(), residual, worst_angle, seconds);
  }
}

}  // namespace
}  // namespace isopatch
