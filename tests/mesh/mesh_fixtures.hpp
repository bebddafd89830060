#pragma once
// Small meshes built in code and a per-test temporary directory, shared by the mesh tests.

#include <isopatch/mesh.hpp>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace isopatch::test {

/// Regular octahedron with vertices at +-1 on the axes; 6 vertices, 8 outward triangles.
inline Mesh octahedron() {
  Mesh m;
  m.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

/// Icosahedron with coordinates that have no short decimal form (golden ratio, scaled by 1/3 and
/// shifted by 0.1), and two attributes whose values include 0.1f, a subnormal, -0 and a huge float.
inline Mesh icosahedron() {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  const double c[12][3] = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                           {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (const auto& p : c) m.positions.push_back(Vec3(p[0], p[1], p[2]) / 3.0 + Vec3::Constant(0.1));
  m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::vector<float> curvature, error;
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    curvature.push_back(0.1f * static_cast<float>(v) - 0.37f);
    const float special[4] = {-0.0f, std::numeric_limits<float>::denorm_min(),
                              std::numeric_limits<float>::max(), -std::numeric_limits<float>::min()};
    error.push_back(v < 4 ? special[v] : static_cast<float>(m.positions[v].x() * 1e-3));
  }
  m.set_attribute("curvature", curvature);
  m.set_attribute("error_1", error);
  return m;
}

/// True when every directed edge appears once and its reverse once: closed and consistently oriented.
inline bool closed_and_oriented(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const Triangle& t : m.triangles)
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
inline bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

/// A fresh directory under the system temporary directory, named after the running test and
/// removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    // Named after the test, plus a random suffix so that concurrent runs never share a directory.
    const std::string name = std::string("isopatch_") + info->test_suite_name() + "_" + info->name() + "_" +
                             std::to_string(std::random_device{}());
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace isopatch::test
