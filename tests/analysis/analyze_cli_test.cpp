// End-to-end tests of `isopatch analyze`: a mesh built in code is written to a file, the tool measures
// it, and its JSON report and its PLY fields are checked against what the mesh is known to be.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "analysis_meshes.hpp"
#include "error_report.hpp"
#include "run_command.hpp"

namespace isopatch {
namespace {

const std::string kCli = ISOPATCH_CLI;

// A level-3 icosphere of the unit sphere (642 vertices, 1280 triangles) written as PLY in `dir`.
std::string write_icosphere(const std::filesystem::path& dir) {
  const auto path = (dir / "icosphere.ply").string();
  write_mesh(test::icosphere(3), path);
  return path;
}

TEST(AnalyzeCli, JsonReportParsesAndDescribesTheMesh) {
  const auto dir = test::scratch_dir("analyze_json");
  const std::string mesh = write_icosphere(dir);
  const auto r = test::run_command(kCli + " analyze " + mesh + " --surface sphere --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);  // throws (fails the test) if not JSON
  EXPECT_EQ(j["mesh"]["vertices"], 642);
  EXPECT_EQ(j["mesh"]["triangles"], 1280);
  EXPECT_EQ(j["topology"]["genus"], 0);
  EXPECT_EQ(j["topology"]["watertight"], true);
  EXPECT_EQ(j["topology"]["outward_oriented"], true);
  EXPECT_EQ(j["self_intersections"]["pairs"], 0);
  EXPECT_EQ(j["valence"]["interior_vertices"], 642);
  EXPECT_EQ(j["valence"]["histogram"][5], 12);
  EXPECT_EQ(j["valence"]["histogram"][6], 630);
  EXPECT_GT(j["shape"]["min_angle_degrees"]["min"].get<double>(), 50.0);
  EXPECT_EQ(j["accuracy"]["surface"], "sphere");
  EXPECT_LT(j["accuracy"]["vertex_distance"]["max"].get<double>(), 1e-6);  // PLY stores doubles
  EXPECT_LT(j["accuracy"]["mean_curvature"]["nrms"].get<double>(), 0.01);
  EXPECT_LT(j["accuracy"]["triangle_normal_error_degrees"]["max"].get<double>(), 2.0);
}

TEST(AnalyzeCli, JsonWithoutSurfaceHasNoAccuracy) {
  const auto dir = test::scratch_dir("analyze_json_plain");
  const std::string mesh = write_icosphere(dir);
  const auto r = test::run_command(kCli + " analyze " + mesh + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("accuracy"));
  EXPECT_NEAR(j["valence"]["share_6"].get<double>(), 630.0 / 642.0, 1e-12);
}

TEST(AnalyzeCli, TextReportNamesEverySection) {
  const auto dir = test::scratch_dir("analyze_text");
  const std::string mesh = write_icosphere(dir);
  const auto r =
      test::run_command(kCli + " analyze " + mesh + " --surface x^2+y^2+z^2-1 --box -2,-2,-2,2,2,2", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* word :
       {"topology", "self-intersections none", "min angle", "valence", "distance", "normals", "nRMS"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word << "\n" << r.out;
}

TEST(AnalyzeCli, WriteStoresTheFieldsAsPlyAttributes) {
  const auto dir = test::scratch_dir("analyze_write");
  const std::string mesh = write_icosphere(dir);
  const auto out = (dir / "fields.ply").string();
  const auto r = test::run_command(kCli + " analyze " + mesh + " --surface sphere --write " + out, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Mesh m = read_mesh(out);
  ASSERT_EQ(m.vertex_count(), 642u);
  for (const char* name : {"mean_curvature", "mean_curvature_exact", "gaussian_curvature",
                           "gaussian_curvature_exact", "distance"}) {
    const std::vector<float>* values = m.find_attribute(name);
    ASSERT_NE(values, nullptr) << name;
    ASSERT_EQ(values->size(), 642u);
  }
  for (float h : *m.find_attribute("mean_curvature")) EXPECT_NEAR(h, 1.0f, 0.01f);
  for (float k : *m.find_attribute("gaussian_curvature_exact")) EXPECT_NEAR(k, 1.0f, 1e-5f);
}

TEST(AnalyzeCli, WriteWithoutSurfaceIsAnInputError) {
  const auto dir = test::scratch_dir("analyze_write_nosurface");
  const std::string mesh = write_icosphere(dir);
  const auto r = test::run_command(kCli + " analyze " + mesh + " --write " + (dir / "f.ply").string(), dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::InvalidArgument));
  EXPECT_NE(r.err.find("--surface"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "f.ply"));
}

TEST(AnalyzeCli, WriteToANonPlyFileIsAnInputError) {
  const auto dir = test::scratch_dir("analyze_write_obj");
  const std::string mesh = write_icosphere(dir);
  const auto r = test::run_command(
      kCli + " analyze " + mesh + " --surface sphere --write " + (dir / "f.obj").string(), dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::InvalidArgument));
}

TEST(AnalyzeCli, MissingMeshIsAnIoError) {
  const auto dir = test::scratch_dir("analyze_missing");
  const auto r = test::run_command(kCli + " analyze " + (dir / "nothing.ply").string(), dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::Io));
  EXPECT_NE(r.err.find("nothing.ply"), std::string::npos) << r.err;
}

TEST(AnalyzeCli, UnknownSurfaceIsReported) {
  const auto dir = test::scratch_dir("analyze_unknown");
  const std::string mesh = write_icosphere(dir);
  const auto r = test::run_command(kCli + " analyze " + mesh + " --surface shpere", dir);
  EXPECT_EQ(r.exit_code, cli::exit_code(ErrorKind::UnknownSurface));
}

}  // namespace
}  // namespace isopatch
