// The B-spline prefilter of a volume window by window with a halo (equal to the whole volume's to
// rounding), and the surface of coefficients mapped from a .npy file (the same as the in-memory one).
#include <gtest/gtest.h>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/volume_surface.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace isopatch {
namespace {

using Shape = std::array<std::size_t, 3>;

std::vector<double> noise(const Shape& shape, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(shape[0] * shape[1] * shape[2]);
  for (double& x : v) x = u(rng);
  return v;
}

std::size_t at(const Shape& shape, std::size_t i, std::size_t j, std::size_t k) {
  return (i * shape[1] + j) * shape[2] + k;
}

/// The largest difference between the whole volume's coefficients and those of windows of `side`
/// samples, each prefiltered alone after reading `halo` more samples on every side (cut at the faces).
double windowed_error(const std::vector<double>& samples, const Shape& shape, std::size_t side,
                      std::size_t halo) {
  std::vector<double> whole = samples;
  interpolating_coefficients(whole, shape);
  double worst = 0.0;
  std::array<std::size_t, 3> lo{};
  for (lo[0] = 0; lo[0] < shape[0]; lo[0] += side)
    for (lo[1] = 0; lo[1] < shape[1]; lo[1] += side)
      for (lo[2] = 0; lo[2] < shape[2]; lo[2] += side) {
        Shape read_lo{}, read_shape{};
        for (std::size_t a = 0; a < 3; ++a) {
          read_lo[a] = lo[a] >= halo ? lo[a] - halo : 0;
          read_shape[a] = std::min(shape[a], lo[a] + side + halo) - read_lo[a];
        }
        std::vector<double> window;
        for (std::size_t i = 0; i < read_shape[0]; ++i)
          for (std::size_t j = 0; j < read_shape[1]; ++j)
            for (std::size_t k = 0; k < read_shape[2]; ++k)
              window.push_back(samples[at(shape, read_lo[0] + i, read_lo[1] + j, read_lo[2] + k)]);
        interpolating_coefficients(window, read_shape);
        for (std::size_t i = lo[0]; i < std::min(shape[0], lo[0] + side); ++i)
          for (std::size_t j = lo[1]; j < std::min(shape[1], lo[1] + side); ++j)
            for (std::size_t k = lo[2]; k < std::min(shape[2], lo[2] + side); ++k) {
              const double mine = window[at(read_shape, i - read_lo[0], j - read_lo[1], k - read_lo[2])];
              worst = std::max(worst, std::abs(mine - whole[at(shape, i, j, k)]));
            }
      }
  return worst;
}

TEST(WindowedPrefilter, HaloGivesTheWholeVolumesCoefficientsToRounding) {
  const Shape shape{70, 45, 53};
  const std::vector<double> samples = noise(shape, 3);
  // Noise is the worst case for the decay (no smoothness helps it). Samples are of size 1.
  EXPECT_LT(windowed_error(samples, shape, 16, kPrefilterHalo), 1e-14);
  // A short halo is visibly wrong: the comparison above can fail.
  EXPECT_GT(windowed_error(samples, shape, 16, 6), 1e-6);
}

TEST(WindowedPrefilter, RefusesAShapeTheSamplesDoNotFill) {
  std::vector<double> samples(24, 1.0);
  EXPECT_THROW(interpolating_coefficients(samples, {2, 3, 5}), InputError);
  EXPECT_THROW(interpolating_coefficients(samples, {1, 4, 6}), InputError);
  EXPECT_NO_THROW(interpolating_coefficients(samples, {2, 3, 4}));
}

/// Writes a version-1 .npy file of `descr` with `shape` and the raw `data` bytes.
void write_npy(const std::filesystem::path& path, const std::string& descr, const std::string& shape,
               bool fortran, const std::string& data) {
  std::string header = "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") +
                       ", 'shape': " + shape + ", }";
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const char len[2] = {static_cast<char>(header.size() & 0xff), static_cast<char>(header.size() >> 8)};
  out.write(len, 2);
  out << header << data;
}

std::string bytes_of(const std::vector<double>& v) {
  std::string s(v.size() * sizeof(double), '\0');
  std::memcpy(s.data(), v.data(), s.size());
  return s;
}

Volume torus_samples(std::size_t n) {
  Volume v;
  v.shape = {n, n + 3, n - 2};
  v.spacing = Vec3(2.2 / double(n - 1), 2.2 / double(n + 2), 1.0 / double(n - 3));
  v.origin = Vec3(-1.1, -1.1, -0.5);
  for (std::size_t i = 0; i < v.shape[0]; ++i)
    for (std::size_t j = 0; j < v.shape[1]; ++j)
      for (std::size_t k = 0; k < v.shape[2]; ++k) {
        const Vec3 p = v.origin + v.spacing.cwiseProduct(Vec3(double(i), double(j), double(k)));
        v.samples.push_back(std::hypot(std::hypot(p.x(), p.y()) - 0.6, p.z()) - 0.25);
      }
  return v;
}

class MappedVolume : public ::testing::Test {
 protected:
  std::filesystem::path path(const std::string& name) {
    const auto p = std::filesystem::temp_directory_path() / ("isopatch_mapped_" + name + ".npy");
    made_.push_back(p);
    return p;
  }
  void TearDown() override {
    for (const auto& p : made_) std::filesystem::remove(p);
  }

 private:
  std::vector<std::filesystem::path> made_;
};

TEST_F(MappedVolume, SameValuesDerivativesBoundsAndMeshAsInMemory) {
  const Volume v = torus_samples(36);
  std::vector<double> coefficients = v.samples;
  interpolating_coefficients(coefficients, v.shape);
  const auto file = path("torus");
  write_npy(file, "<f8",
            "(" + std::to_string(v.shape[0]) + ", " + std::to_string(v.shape[1]) + ", " +
                std::to_string(v.shape[2]) + ")",
            false, bytes_of(coefficients));
  const SurfacePtr memory = volume_surface(v, 0.0);
  const SurfacePtr mapped = mapped_volume_surface(file.string(), v.spacing, v.origin, 0.0);
  EXPECT_EQ(mapped->box().lo, memory->box().lo);
  EXPECT_EQ(mapped->box().hi, memory->box().hi);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  for (int n = 0; n < 300; ++n) {
    const Vec3 p(u(rng), u(rng), 0.5 * u(rng));
    const SecondOrder a = memory->second_order(p), b = mapped->second_order(p);
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.gradient, b.gradient);
    EXPECT_EQ(a.hessian, b.hessian);
    const Vec3 q(u(rng), u(rng), 0.5 * u(rng));
    const Box box{p.cwiseMin(q), p.cwiseMax(q)};
    const auto ba = memory->gradient_bound(box), bb = mapped->gradient_bound(box);
    ASSERT_TRUE(ba && bb);
    EXPECT_EQ(ba->value.lo, bb->value.lo);
    EXPECT_EQ(ba->value.hi, bb->value.hi);
  }
  Settings settings;
  settings.edge_length = 0.08;
  const Mesh a = mesh_surface(*memory, settings), b = mesh_surface(*mapped, settings);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST_F(MappedVolume, RefusesFilesItCannotMapAsCoefficients) {
  const std::string data = bytes_of(std::vector<double>(2 * 3 * 4, 0.5));
  const auto expect_io = [](const std::filesystem::path& p, const std::string& words) {
    try {
      mapped_volume_surface(p.string(), Vec3::Ones(), Vec3::Zero(), 0.0);
      ADD_FAILURE() << words;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expect_io(path("missing"), "cannot open");
  struct Bad {
    const char *name, *descr, *shape;
    bool fortran;
    std::size_t bytes;
    const char* words;
  };
  for (const Bad& bad : {Bad{"single", "<f4", "(2, 3, 4)", false, data.size() / 2, "float64"},
                         Bad{"fortran", "<f8", "(2, 3, 4)", true, data.size(), "C order"},
                         Bad{"short", "<f8", "(2, 3, 5)", false, data.size(), "bytes of data"},
                         Bad{"flat", "<f8", "(6, 4)", false, data.size(), "dimensions"},
                         Bad{"thin", "<f8", "(1, 6, 4)", false, data.size(), "at least 2"}}) {
    const auto file = path(bad.name);
    write_npy(file, bad.descr, bad.shape, bad.fortran, data.substr(0, bad.bytes));
    expect_io(file, bad.words);
  }
  const auto good = path("good");
  write_npy(good, "<f8", "(2, 3, 4)", false, data);
  EXPECT_NO_THROW(mapped_volume_surface(good.string(), Vec3::Ones(), Vec3::Zero(), 0.0));
  EXPECT_THROW(mapped_volume_surface(good.string(), Vec3(1, 0, 1), Vec3::Zero(), 0.0), InputError);
  EXPECT_THROW(mapped_volume_surface(good.string(), Vec3::Ones(), Vec3::Zero(), std::nan("")), InputError);
}

}  // namespace
}  // namespace isopatch
