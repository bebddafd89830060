// The tricubic B-spline surface of a sampled volume: interpolation, exact derivatives, sound bounds,
// errors, and meshes of sampled analytic surfaces.
#include <gtest/gtest.h>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/volume_surface.hpp>

#include <cmath>
#include <random>

namespace isopatch {
namespace {

/// f sampled on an n^3 grid over [-1, 1]^3.
template <class F>
Volume sampled(F f, std::size_t n) {
  Volume v;
  v.shape = {n, n, n};
  v.spacing = Vec3::Constant(2.0 / static_cast<double>(n - 1));
  v.origin = Vec3::Constant(-1.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k)
        v.samples.push_back(f(v.origin + v.spacing.cwiseProduct(Vec3(double(i), double(j), double(k)))));
  return v;
}

double sphere(const Vec3& p) {
  return p.norm() - 0.6;
}
double torus(const Vec3& p) {
  const double q = std::hypot(p.x(), p.y()) - 0.6;
  return std::hypot(q, p.z()) - 0.25;
}

Volume random_volume(std::array<std::size_t, 3> shape, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Volume v;
  v.shape = shape;
  v.spacing = Vec3(0.5, 0.7, 0.3);
  v.origin = Vec3(-1, 0.5, 2);
  for (std::size_t n = 0; n < shape[0] * shape[1] * shape[2]; ++n) v.samples.push_back(u(rng));
  return v;
}

TEST(VolumeSurface, InterpolatesEverySample) {
  const Volume v = random_volume({5, 2, 7}, 1);
  const SurfacePtr s = volume_surface(v, 0.25);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 2; ++j)
      for (std::size_t k = 0; k < 7; ++k) {
        const Vec3 p = v.origin + v.spacing.cwiseProduct(Vec3(double(i), double(j), double(k)));
        EXPECT_NEAR(s->value(p), v.at(i, j, k) - 0.25, 1e-12);
      }
}

TEST(VolumeSurface, DerivativesAreThoseOfTheValue) {
  const Volume v = random_volume({6, 5, 4}, 2);
  const SurfacePtr s = volume_surface(v, 0.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 1.2);  // also a little beyond the grid (mirror)
  const double h = 1e-5;
  for (int n = 0; n < 200; ++n) {
    const Box e = v.extent();
    const Vec3 p = e.lo + e.size().cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
    const SecondOrder so = s->second_order(p);
    EXPECT_NEAR(so.value, s->value(p), 1e-14);
    for (int a = 0; a < 3; ++a) {
      Vec3 d = Vec3::Zero();
      d[a] = h;
      EXPECT_NEAR(so.gradient[a], (s->value(p + d) - s->value(p - d)) / (2 * h), 1e-5) << p.transpose();
      const Vec3 dg = (s->value_gradient(p + d).gradient - s->value_gradient(p - d).gradient) / (2 * h);
      for (int b = 0; b < 3; ++b) EXPECT_NEAR(so.hessian(a, b), dg[b], 1e-4);
    }
  }
}

TEST(VolumeSurface, BoundsHoldEverySampledValue) {
  const Volume v = random_volume({7, 6, 5}, 4);
  const SurfacePtr s = volume_surface(v, 0.1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.3, 1.3);
  const Box e = v.extent();
  for (int n = 0; n < 100; ++n) {
    Vec3 a = e.lo + e.size().cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
    Vec3 b = e.lo + e.size().cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
    const Box box{a.cwiseMin(b), a.cwiseMax(b)};
    const std::optional<IntervalGradient> bound = s->gradient_bound(box);
    ASSERT_TRUE(bound);
    EXPECT_EQ(s->bound(box)->lo, bound->value.lo);
    std::uniform_real_distribution<double> t(0.0, 1.0);
    for (int m = 0; m < 50; ++m) {
      const Vec3 p = box.lo + box.size().cwiseProduct(Vec3(t(rng), t(rng), t(rng)));
      const ValueGradient vg = s->value_gradient(p);
      EXPECT_TRUE(bound->value.contains(vg.value));
      for (int c = 0; c < 3; ++c)
        EXPECT_TRUE(bound->gradient[static_cast<std::size_t>(c)].contains(vg.gradient[c]));
    }
  }
}

TEST(VolumeSurface, ClearErrors) {
  Volume v = random_volume({3, 3, 3}, 6);
  EXPECT_THROW(volume_surface(v, 5.0), NoSurfaceError);
  try {
    volume_surface(v, -5.0);
    FAIL();
  } catch (const NoSurfaceError& e) {
    EXPECT_NE(std::string(e.what()).find("no sample of the volume crosses level -5"), std::string::npos);
  }
  EXPECT_THROW(volume_surface(v, std::nan("")), InputError);
  Volume with_inf = v;
  with_inf.samples[5] = INFINITY;
  try {
    volume_surface(with_inf, 0.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "the volume has an infinity at index (0, 1, 2)");
  }
  Volume flat = v;
  flat.shape = {1, 3, 9};
  EXPECT_THROW(volume_surface(flat, 0.0), InputError);
  Volume bad_spacing = v;
  bad_spacing.spacing.y() = 0.0;
  EXPECT_THROW(volume_surface(bad_spacing, 0.0), InputError);
}

/// A sampled analytic surface meshed with the defaults: watertight, regular, close to the surface.
void expect_good_mesh(double (*f)(const Vec3&), std::size_t n, int genus, double max_distance) {
  const SurfacePtr s = volume_surface(sampled(f, n), 0.0);
  Settings settings;
  const Mesh mesh = mesh_surface(*s, settings);
  const QualityReport q = analyze_quality(mesh, s.get());
  EXPECT_TRUE(q.topology.watertight()) << n;
  EXPECT_EQ(q.topology.genus, genus) << n;
  EXPECT_GE(q.valence.share_6, 0.90) << n;
  EXPECT_GE(q.shape.min_angle.min, 20.0) << n;
  double worst = 0.0;
  for (const Vec3& p : mesh.positions) worst = std::max(worst, std::abs(f(p)));
  EXPECT_LT(worst, max_distance) << n;  // |f| of these is the distance to the analytic surface
  EXPECT_LT(q.accuracy->vertex_distance.max, 1e-9) << n;  // on the interpolant itself
}

TEST(VolumeSurface, SampledSphereMeshesWell) {
  expect_good_mesh(&sphere, 32, 0, 2e-5);  // measured 5e-6 and 7e-8 (the interpolation error, ~h^4)
  expect_good_mesh(&sphere, 64, 0, 5e-7);
}

TEST(VolumeSurface, SampledTorusMeshesWell) {
  expect_good_mesh(&torus, 32, 1, 2e-3);  // measured 8e-4 and 2e-5
  expect_good_mesh(&torus, 64, 1, 1e-4);
}

}  // namespace
}  // namespace isopatch
