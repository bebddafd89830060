// Control polyhedra: the exact sphere cases (cube -> radius sqrt(3), octahedron -> unit sphere), the
// weights through the reference points, the options, and the topology that is refused.
#include "composite_model/control_polyhedron.hpp"
#include "composite_model/composite_checks.hpp"
#include "composite_model/ipatch_surface.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace isopatch {
namespace {

ControlPolyhedron cube() {
  ControlPolyhedron c;
  for (int k = 0; k < 8; ++k)
    c.mesh.vertices.push_back({k & 4 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 1 ? 1.0 : -1.0});
  c.mesh.faces = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  return c;
}

ControlPolyhedron octahedron() {
  ControlPolyhedron c;
  c.mesh.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  c.mesh.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return c;
}

/// The cube with one corner pulled out, stretched: no symmetry.
ControlPolyhedron pulled_box() {
  ControlPolyhedron p = cube();
  p.mesh.vertices[7] = Vec3(1.4, 1.2, 1.3);
  for (Vec3& v : p.mesh.vertices) v = Vec3(1.5 * v.x(), v.y(), 0.8 * v.z());
  return p;
}

/// The largest |radius - expected| of the composite's zero set along random rays from the origin, each
/// ray bisected inside the patch whose region holds it.
double radial_error(const Composite& c, double expected, int rays) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  double worst = 0.0;
  int hits = 0;
  for (int i = 0; i < rays; ++i) {
    const Vec3 u = Vec3(g(rng), g(rng), g(rng)).normalized();
    for (const CompositePatch& p : c.patches) {
      const auto& f = dynamic_cast<const IPatchSurface&>(*p.surface);
      if (f.region_margin(expected * u) < 0.0) continue;
      double lo = 0.5 * expected, hi = 1.5 * expected;
      const bool lo_sign = f.value(lo * u) > 0.0;
      if (lo_sign == (f.value(hi * u) > 0.0)) return HUGE_VAL;  // no root on the ray
      for (int k = 0; k < 100; ++k) {
        const double m = 0.5 * (lo + hi);
        ((f.value(m * u) > 0.0) == lo_sign ? lo : hi) = m;
      }
      worst = std::max(worst, std::abs(lo - expected));
      ++hits;
    }
  }
  return hits >= rays ? worst : HUGE_VAL;
}

TEST(ControlPolyhedron, CubeGivesTheSphereOfRadiusSqrt3) {
  const Composite c = build_control_polyhedron(cube());
  ASSERT_EQ(c.patches.size(), 6u);
  ASSERT_EQ(c.curves.size(), 12u);
  for (const ConicArc& a : c.curves) EXPECT_NEAR(a.weight, std::sqrt(2.0 / 3.0), 1e-12);
  EXPECT_LT(radial_error(c, std::sqrt(3.0), 2000), 1e-9);
  // F itself is (|x|^2 - 3) / 3 in every cell (each ribbon is that sphere minus B^2 / 3).
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  double worst = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 x(u(rng), u(rng), u(rng));
    for (const CompositePatch& p : c.patches) {
      const auto& f = dynamic_cast<const IPatchSurface&>(*p.surface);
      if (f.region_margin(x) > 1e-3)
        worst = std::max(worst, std::abs(f.value(x) - (x.squaredNorm() - 3.0) / 3.0));
    }
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(ControlPolyhedron, OctahedronGivesTheUnitSphere) {
  const Composite c = build_control_polyhedron(octahedron());
  ASSERT_EQ(c.patches.size(), 8u);
  for (const CompositePatch& p : c.patches) EXPECT_EQ(p.sides.size(), 3u);
  for (const ConicArc& a : c.curves) EXPECT_NEAR(a.weight, std::sqrt(0.5), 1e-12);
  EXPECT_LT(radial_error(c, 1.0, 2000), 1e-9);
}

TEST(ControlPolyhedron, CornerDirectionsAreTheVertexNormals) {
  const Composite c = build_control_polyhedron(cube());
  for (const CompositePatch& p : c.patches) {
    for (std::size_t k = 0; k < p.sides.size(); ++k) {
      const ConicArc& a = c.curves[p.sides[k].curve];
      const Vec3 corner = p.sides[k].reversed ? a.end : a.start;
      EXPECT_LT((p.corner_directions[k] - corner.normalized()).norm(), 1e-12);
    }
  }
}

TEST(ControlPolyhedron, InwardFacesAreReversedToTheSameShape) {
  ControlPolyhedron inward = cube();
  for (auto& f : inward.mesh.faces) std::reverse(f.begin(), f.end());
  const Composite c = build_control_polyhedron(inward);
  EXPECT_LT(radial_error(c, std::sqrt(3.0), 300), 1e-9);
}

TEST(ControlPolyhedron, EdgeOptionsShapeTheirCurve) {
  ControlPolyhedron p = cube();
  p.edges.push_back({0, 1, 0.6, std::nullopt});
  const Composite a = build_control_polyhedron(p);
  bool found = false;
  for (const ConicArc& arc : a.curves) found = found || std::abs(arc.weight - 0.6) < 1e-15;
  EXPECT_TRUE(found);
  // A point on the default circular arc gives back the circular weight.
  const Composite b = build_control_polyhedron(cube());
  ControlPolyhedron q = cube();
  q.edges.push_back({0, 1, std::nullopt, b.curves[0].point(0.3)});
  const Composite c = build_control_polyhedron(q);
  EXPECT_NEAR(c.curves[0].weight, b.curves[0].weight, 1e-12);
  q.edges.back().through = Vec3(5.0, 5.0, 5.0);
  EXPECT_THROW(build_control_polyhedron(q), InputError);
  ControlPolyhedron r = cube();
  r.edges.push_back({0, 7, 0.5, std::nullopt});  // a diagonal, not an edge
  EXPECT_THROW(build_control_polyhedron(r), InputError);
}

TEST(ControlPolyhedron, GivenCentresAndNormalsAreUsed) {
  ControlPolyhedron p = cube();
  p.faces.push_back({1, Vec3(1.6, 0.1, 0.0), {1.0, 2.0, 1.0, 1.0}});
  const Composite c = build_control_polyhedron(p);
  EXPECT_LT(std::abs(c.patches[1].surface->value(Vec3(1.6, 0.1, 0.0))), 1e-13);
  ControlPolyhedron q = cube();
  q.normals.assign(8, std::nullopt);
  q.normals[7] = Vec3(1.0, 1.2, 0.9);
  EXPECT_NO_THROW(check_composite_closed(build_control_polyhedron(q)));
  q.faces.push_back({1, Vec3(-1.6, 0.0, 0.0), {}});  // outside face 2's region
  EXPECT_THROW(build_control_polyhedron(q), InputError);
}

TEST(ControlPolyhedron, BadTopologyIsRefused) {
  const auto refuses = [](ControlPolyhedron p) { EXPECT_THROW(build_control_polyhedron(p), InputError); };
  ControlPolyhedron p = cube();
  p.mesh.faces[0] = {0, 1};  // fewer than 3 vertices
  refuses(p);
  p = cube();
  p.mesh.faces[0] = {0, 1, 1, 2};  // a repeated vertex
  refuses(p);
  p = cube();
  p.mesh.faces.pop_back();  // open
  refuses(p);
  p = cube();
  std::reverse(p.mesh.faces[2].begin(), p.mesh.faces[2].end());  // inconsistently oriented
  refuses(p);
  p = cube();
  p.mesh.vertices.push_back(Vec3(3, 3, 3));  // unused vertex
  refuses(p);
  p = cube();
  p.mesh.faces.push_back({0, 1, 3, 2});  // an edge in three faces
  refuses(p);
  // Two octahedra sharing one vertex: every edge has two faces, the shared vertex two fans.
  ControlPolyhedron two = octahedron();
  const std::size_t base = two.mesh.vertices.size();
  for (std::size_t v = 0; v < base; ++v) {
    if (v != 1) two.mesh.vertices.push_back(octahedron().mesh.vertices[v] + Vec3(-2, 0, 0));
  }
  const auto map = [&](std::uint32_t v) -> std::uint32_t {
    if (v == 0) return 1;  // the right tip of the moved copy is the left tip of the first
    return static_cast<std::uint32_t>(base + (v < 1 ? v : v - 1));
  };
  for (const auto& f : octahedron().mesh.faces) two.mesh.faces.push_back({map(f[0]), map(f[1]), map(f[2])});
  refuses(two);
}

TEST(ControlPolyhedron, TheRibbonsAreG1AtTheVertices) {
  // Every ribbon at a vertex has the vertex normal as its gradient direction there.
  const Composite c = build_control_polyhedron(cube());
  for (const CompositePatch& p : c.patches) {
    const auto& f = dynamic_cast<const IPatchSurface&>(*p.surface);
    for (std::size_t k = 0; k < p.sides.size(); ++k) {
      const ConicArc& a = c.curves[p.sides[k].curve];
      for (const Vec3& corner : {a.start, a.end}) {
        const Vec3 g = f.ribbons()[k]->value_gradient(corner).gradient.normalized();
        EXPECT_LT((g - corner.normalized()).norm(), 1e-12);
      }
    }
  }
}

TEST(ControlPolyhedron, DefaultWeightsPassThroughTheDefaultReferencePoints) {
  // The cube's reference points are its face centres pushed out to the corner radius, sqrt(3).
  const Composite c = build_control_polyhedron(cube());
  const Vec3 centres[6] = {-Vec3::UnitX(), Vec3::UnitX(),  -Vec3::UnitY(),
                           Vec3::UnitY(),  -Vec3::UnitZ(), Vec3::UnitZ()};
  for (int f = 0; f < 6; ++f) {
    EXPECT_LT(std::abs(c.patches[f].surface->value(std::sqrt(3.0) * centres[f])), 1e-14) << c.patches[f].name;
  }
}

TEST(ControlPolyhedron, GradientsAndHessiansOfAnAsymmetricPatchMatchDifferences) {
  const Composite c = build_control_polyhedron(pulled_box());
  std::mt19937 rng(9);
  std::normal_distribution<double> g;
  const double h = 1e-5;
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 x = 1.6 * Vec3(g(rng), g(rng), g(rng)).normalized();
    for (const CompositePatch& patch : c.patches) {
      const auto& f = dynamic_cast<const IPatchSurface&>(*patch.surface);
      if (f.region_margin(x) < 0.05) continue;
      const SecondOrder s = f.second_order(x);
      for (int k = 0; k < 3; ++k) {
        const Vec3 d = h * Vec3::Unit(k);
        const double fd = (f.value(x + d) - f.value(x - d)) / (2 * h);
        EXPECT_NEAR(s.gradient(k), fd, 1e-6 * (1.0 + std::abs(fd)));
        const Vec3 gd = (f.value_gradient(x + d).gradient - f.value_gradient(x - d).gradient) / (2 * h);
        for (int l = 0; l < 3; ++l) EXPECT_NEAR(s.hessian(l, k), gd(l), 1e-5 * (1.0 + std::abs(gd(l))));
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
}

TEST(ControlPolyhedron, TheBoxHoldsTheSurface) {
  // The piecewise function (each point's value from the patch whose region holds it most deeply) along
  // rays from the centroid (the origin here): its first crossing lies in the composite's box.
  for (const ControlPolyhedron& p : {cube(), octahedron(), pulled_box()}) {
    const Composite c = build_control_polyhedron(p);
    const auto piecewise = [&](const Vec3& x) {
      double best = -HUGE_VAL, value = 0.0;
      for (const CompositePatch& patch : c.patches) {
        const auto& f = dynamic_cast<const IPatchSurface&>(*patch.surface);
        if (f.region_margin(x) > best) {
          best = f.region_margin(x);
          value = f.value(x);
        }
      }
      return value;
    };
    EXPECT_LT(piecewise(Vec3::Zero()), 0.0);
    std::mt19937 rng(10);
    std::normal_distribution<double> g;
    for (int i = 0; i < 500; ++i) {
      const Vec3 u = Vec3(g(rng), g(rng), g(rng)).normalized();
      bool crossed = false;
      for (int t = 1; t <= 400 && !crossed; ++t) {
        const Vec3 x = (t / 400.0) * c.box.diagonal() * u;
        if (piecewise(x) > 0.0) {
          EXPECT_TRUE(c.box.contains(x)) << x.transpose();
          crossed = true;
        }
      }
      EXPECT_TRUE(crossed);
    }
  }
}

TEST(ControlPolyhedron, AReflexCornerWithDefaultNormalsIsRefusedClearly) {
  // An L-shaped prism: at its inner corner the default normals of an edge's two ends are equal and not
  // perpendicular to it, which asks for an S-shaped curve.
  ControlPolyhedron l;
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (int z = 0; z < 2; ++z) {
    for (const auto& q : xy) l.mesh.vertices.push_back({q[0], q[1], double(z)});
  }
  l.mesh.faces.push_back({5, 4, 3, 2, 1, 0});
  l.mesh.faces.push_back({6, 7, 8, 9, 10, 11});
  for (std::uint32_t i = 0; i < 6; ++i) l.mesh.faces.push_back({i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6});
  try {
    build_control_polyhedron(l);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("S-shaped"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace isopatch
