// Analytic curvature at points where it is known in closed form, and discrete curvature on fine
// meshes of the sphere and the torus (convergence, Gauss-Bonnet, sign).
#include <isopatch/callable_surface.hpp>
#include <isopatch/curvature.hpp>
#include <isopatch/metrics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis_meshes.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

TEST(AnalyticCurvature, SphereHasHOneOverRAndKOneOverRSquared) {
  const double R = 2.0;
  const SurfacePtr s = test::sphere(R, Vec3::Zero(), 2.5);
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(1, 2, -2).normalized()}) {
    const PointCurvature c = analytic_curvature(*s, R * d);
    EXPECT_NEAR(c.mean, 1.0 / R, 1e-14);
    EXPECT_NEAR(c.gaussian, 1.0 / (R * R), 1e-14);
  }
}

TEST(AnalyticCurvature, SignFollowsTheGradient) {
  // f > 0 inside: the gradient points inward and the sphere becomes concave (H < 0); K keeps its sign.
  const SurfacePtr inside_out =
      make_surface([](auto x, auto y, auto z) { return 1.0 - x * x - y * y - z * z; },
                   Box{Vec3::Constant(-2), Vec3::Constant(2)});
  const PointCurvature c = analytic_curvature(*inside_out, Vec3(0, 0, 1));
  EXPECT_NEAR(c.mean, -1.0, 1e-14);
  EXPECT_NEAR(c.gaussian, 1.0, 1e-14);
}

TEST(AnalyticCurvature, TorusAtItsEquatorsAndTop) {
  const double R = 1.0, r = 0.4;
  const SurfacePtr t = test::torus(R, r);
  const PointCurvature outer = analytic_curvature(*t, Vec3(R + r, 0, 0));
  EXPECT_NEAR(outer.mean, (R + 2 * r) / (2 * r * (R + r)), 1e-12);
  EXPECT_NEAR(outer.gaussian, 1.0 / (r * (R + r)), 1e-12);
  const PointCurvature inner = analytic_curvature(*t, Vec3(0, R - r, 0));
  EXPECT_NEAR(inner.mean, (R - 2 * r) / (2 * r * (R - r)), 1e-12);
  EXPECT_GT(inner.mean, 0.0);  // 1/r beats -1/(R - r) for r < R/2
  EXPECT_NEAR(inner.gaussian, -1.0 / (r * (R - r)), 1e-12);
  const PointCurvature top = analytic_curvature(*t, Vec3(R, 0, r));  // principal curvatures 1/r and 0
  EXPECT_NEAR(top.mean, 1.0 / (2 * r), 1e-12);
  EXPECT_NEAR(top.gaussian, 0.0, 1e-12);
}

TEST(AnalyticCurvature, UndefinedAtACriticalPoint) {
  const PointCurvature c = analytic_curvature(*test::sphere(), Vec3::Zero());  // grad f = 0
  EXPECT_TRUE(std::isnan(c.mean));
  EXPECT_TRUE(std::isnan(c.gaussian));
}

TEST(DiscreteCurvature, FineIcosphereConvergesToOneOverR) {
  const double R = 1.5;
  const Mesh m = test::icosphere(5, R);  // 10,242 vertices
  const DiscreteCurvature d = discrete_curvature(m);
  double error_squares = 0.0, exact_squares = 0.0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    ASSERT_TRUE(d.interior[v]);
    EXPECT_GT(d.mean[v], 0.0);
    error_squares += (d.mean[v] - 1.0 / R) * (d.mean[v] - 1.0 / R);
    exact_squares += 1.0 / (R * R);
  }
  EXPECT_LT(std::sqrt(error_squares / exact_squares), 0.01);
}

TEST(DiscreteCurvature, AngleDeficitIntegratesToFourPiAndAreasTileTheMesh) {
  const Mesh m = test::icosphere(4);
  const DiscreteCurvature d = discrete_curvature(m);
  double total_k = 0.0, total_area = 0.0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    total_k += d.gaussian[v] * d.area[v];
    total_area += d.area[v];
  }
  EXPECT_NEAR(total_k, 4.0 * std::numbers::pi, 1e-9);
  double triangle_area = 0.0;
  for (const Triangle& t : m.triangles)
    triangle_area +=
        0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
  EXPECT_NEAR(total_area, triangle_area, 1e-10 * triangle_area);
}

TEST(DiscreteCurvature, ObtuseTrianglesStillTileTheArea) {
  // A squashed icosphere has obtuse triangles; the mixed areas must still sum to the mesh area.
  Mesh m = test::icosphere(2);
  for (Vec3& p : m.positions) p.z() *= 0.2;
  const DiscreteCurvature d = discrete_curvature(m);
  double total_area = 0.0, total_k = 0.0, triangle_area = 0.0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    total_area += d.area[v];
    total_k += d.gaussian[v] * d.area[v];
  }
  for (const Triangle& t : m.triangles)
    triangle_area +=
        0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
  EXPECT_NEAR(total_area, triangle_area, 1e-10 * triangle_area);
  EXPECT_NEAR(total_k, 4.0 * std::numbers::pi, 1e-9);
}

TEST(DiscreteCurvature, ReversedOrientationFlipsMeanNotGaussian) {
  Mesh m = test::icosphere(3);
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  const DiscreteCurvature d = discrete_curvature(m);
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    EXPECT_LT(d.mean[v], 0.0);
    EXPECT_GT(d.gaussian[v], 0.0);
  }
}

TEST(DiscreteCurvature, RegularTorusMatchesTheAnalyticValues) {
  const Mesh m = test::parametric_torus(120, 48);
  const AccuracyReport a = analyze_accuracy(m, *test::torus());
  EXPECT_EQ(a.mean_curvature.vertices, m.vertex_count());
  EXPECT_LT(a.mean_curvature.nrms, 0.002);      // measured 7.5e-4
  EXPECT_LT(a.gaussian_curvature.nrms, 0.004);  // measured 1.4e-3
  const DiscreteCurvature d = discrete_curvature(m);
  double total_k = 0.0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) total_k += d.gaussian[v] * d.area[v];
  EXPECT_NEAR(total_k, 0.0, 1e-9);  // chi = 0
}

TEST(DiscreteCurvature, ConvergesAtSecondOrderOnARegularTorus) {
  const SurfacePtr torus = test::torus();
  const double coarse = analyze_accuracy(test::parametric_torus(60, 24), *torus).mean_curvature.nrms;
  const double fine = analyze_accuracy(test::parametric_torus(120, 48), *torus).mean_curvature.nrms;
  EXPECT_GT(coarse / fine, 3.0);  // halving the step divides the error by about 4
}

TEST(DiscreteCurvature, IrregularSamplingOfTheTorusRaisesTheError) {
  // Same connectivity (all valence 6), same surface, vertices moved along it by up to 10% of a step:
  // the cotangent formula loses its accuracy, which is what H nRMS is there to show (Xu 2004).
  const SurfacePtr torus = test::torus();
  const double regular = analyze_accuracy(test::parametric_torus(120, 48), *torus).mean_curvature.nrms;
  const double jittered =
      analyze_accuracy(test::parametric_torus(120, 48, 1.0, 0.4, 0.2), *torus).mean_curvature.nrms;
  EXPECT_GT(jittered, 10.0 * regular);
}

TEST(DiscreteCurvature, BoundaryAndFlatFan) {
  const Mesh fan = test::hexagon_fan();
  const DiscreteCurvature d = discrete_curvature(fan);
  EXPECT_TRUE(d.interior[0]);
  EXPECT_NEAR(d.mean[0], 0.0, 1e-14);
  EXPECT_NEAR(d.gaussian[0], 0.0, 1e-12);
  // Six equilateral triangles of side 1, none obtuse: the Voronoi cell is a third of each.
  EXPECT_NEAR(d.area[0], 6.0 * std::sqrt(3.0) / 4.0 / 3.0, 1e-14);
  for (std::size_t v = 1; v < 7; ++v) {
    EXPECT_FALSE(d.interior[v]);
    EXPECT_TRUE(std::isnan(d.mean[v]));
    EXPECT_TRUE(std::isnan(d.gaussian[v]));
  }
}

TEST(CurvatureFields, AttachesNamedAttributesWithTheExpectedValues) {
  Mesh m = test::icosphere(3);
  m.triangles.pop_back();  // a hole: its three vertices get no discrete curvature
  attach_fields(m, *test::sphere());
  for (const char* name : {"mean_curvature", "mean_curvature_exact", "gaussian_curvature",
                           "gaussian_curvature_exact", "distance"})
    ASSERT_NE(m.find_attribute(name), nullptr) << name;
  const auto& h = *m.find_attribute("mean_curvature");
  const auto& h_exact = *m.find_attribute("mean_curvature_exact");
  const auto& k_exact = *m.find_attribute("gaussian_curvature_exact");
  const auto& distance = *m.find_attribute("distance");
  std::size_t undefined = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    EXPECT_NEAR(h_exact[v], 1.0f, 1e-6f);
    EXPECT_NEAR(k_exact[v], 1.0f, 1e-6f);
    EXPECT_NEAR(distance[v], 0.0f, 1e-6f);
    if (std::isnan(h[v]))
      ++undefined;
    else
      EXPECT_NEAR(h[v], 1.0f, 0.05f);
  }
  EXPECT_EQ(undefined, 3u);
  m.validate();
}

}  // namespace
}  // namespace isopatch
