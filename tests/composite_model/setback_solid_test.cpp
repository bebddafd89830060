// Setback vertex blends: the rounded box's 26 patches, the vertex blends' interpolation of their edge
// blends and faces (G1), the reference point, the validity check, and the solids that are refused.
#include "composite_model/setback_solid.hpp"
#include "composite_model/composite_checks.hpp"
#include "composite_model/ipatch_surface.hpp"
#include "composite_model/patch_validity.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

namespace isopatch {
namespace {

SetbackSolid box(double r, double s, bool conic = true) {
  SetbackSolid b;
  for (int k = 0; k < 8; ++k)
    b.mesh.vertices.push_back({k & 4 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 1 ? 1.0 : -1.0});
  b.mesh.faces = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  b.radius = r;
  b.setback = s;
  b.conic_face_curves = conic;
  return b;
}

TEST(SetbackSolid, RoundedBoxHas26ClosedPatches) {
  for (bool conic : {true, false}) {
    const Composite c = build_setback_solid(box(0.3, 0.6, conic));
    ASSERT_EQ(c.patches.size(), 26u);
    std::map<std::size_t, int> by_sides;
    for (const CompositePatch& p : c.patches) ++by_sides[p.sides.size()];
    EXPECT_EQ(by_sides[8], 6);   // faces
    EXPECT_EQ(by_sides[4], 12);  // edge blends
    EXPECT_EQ(by_sides[6], 8);   // vertex blends
    EXPECT_EQ(c.curves.size(), 72u);
    EXPECT_NO_THROW(check_composite_closed(c));
  }
}

TEST(SetbackSolid, VertexBlendMeetsItsRibbonsWithG1) {
  const Composite c = build_setback_solid(box(0.3, 0.6));
  for (const CompositePatch& p : c.patches) {
    const auto* f = dynamic_cast<const IPatchSurface*>(p.surface.get());
    if (!f) continue;
    ASSERT_EQ(f->sides(), 6u);
    for (std::size_t k = 0; k < 6; ++k) {
      const ConicArc& a = c.curves[p.sides[k].curve];
      for (int j = 1; j < 20; ++j) {
        const Vec3 x = a.point(j / 20.0);
        EXPECT_LT(std::abs(f->ribbons()[k]->value(x)), 1e-12);
        EXPECT_LT(std::abs(f->bounds()[k]->value(x)), 1e-12);
        const ValueGradient g = f->value_gradient(x);
        EXPECT_LT(std::abs(g.value), 1e-12);
        const Vec3 gr = f->ribbons()[k]->value_gradient(x).gradient;
        EXPECT_LT(g.gradient.normalized().cross(gr.normalized()).norm(), 1e-8);
        // Every other side's bound is positive on this side's curve: the curve is in the region.
        for (std::size_t i = 0; i < 6; ++i) {
          if (i != k) {
            EXPECT_GT(f->bounds()[i]->value(x), 0.0);
          }
        }
      }
    }
  }
}

TEST(SetbackSolid, CubeCornerBlendIsSymmetricAndPassesNearTheNote) {
  // Corner (1,1,1), r = 0.3, s = 0.6: the reference point is the corners' centroid, at distance
  // (r + s) / sqrt(3) from the vertex along the diagonal, and the patch passes through it.
  const Composite c = build_setback_solid(box(0.3, 0.6));
  const Vec3 v(1, 1, 1);
  const Vec3 centre = v - Vec3::Constant(0.3);
  bool found = false;
  for (const CompositePatch& p : c.patches) {
    if (p.name != "vertex blend 8") continue;
    found = true;
    EXPECT_LT(std::abs(p.surface->value(centre)), 1e-13);
    // Symmetric under permuting the axes.
    const Vec3 x(0.8, 0.75, 0.7);
    EXPECT_NEAR(p.surface->value(x), p.surface->value(Vec3(0.75, 0.7, 0.8)), 1e-13);
  }
  EXPECT_TRUE(found);
}

TEST(SetbackSolid, ValidityCheckFindsNothingOnTheRoundedBox) {
  for (bool conic : {true, false}) {
    const auto findings = check_patch_validity(build_setback_solid(box(0.3, 0.6, conic)));
    for (const auto& f : findings) ADD_FAILURE() << f.message;
  }
}

TEST(SetbackSolid, VertexBlendDerivativesMatchDifferences) {
  const Composite c = build_setback_solid(box(0.3, 0.6));
  const auto& f = dynamic_cast<const IPatchSurface&>(*c.patches.back().surface);  // vertex blend 8 at (1,1,1)
  const double h = 1e-6;
  int checked = 0;
  for (double a = 0.45; a <= 0.95; a += 0.05) {
    for (double b = 0.45; b <= 0.95; b += 0.05) {
      const Vec3 x(a, b, 0.8);
      if (f.region_margin(x) < 0.02) continue;
      const SecondOrder s = f.second_order(x);
      for (int k = 0; k < 3; ++k) {
        const Vec3 d = h * Vec3::Unit(k);
        const double fd = (f.value(x + d) - f.value(x - d)) / (2 * h);
        EXPECT_NEAR(s.gradient(k), fd, 1e-6 * (1.0 + std::abs(fd)));
        const Vec3 gd = (f.value_gradient(x + d).gradient - f.value_gradient(x - d).gradient) / (2 * h);
        for (int l = 0; l < 3; ++l) EXPECT_NEAR(s.hessian(l, k), gd(l), 1e-4 * (1.0 + std::abs(gd(l))));
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(SetbackSolid, UnequalSetbacksStillClose) {
  SetbackSolid b = box(0.25, 0.6);
  b.vertex_setbacks.push_back({7, 0.75});
  b.edge_radii.push_back({6, 7, 0.35});
  const Composite c = build_setback_solid(b);
  EXPECT_NO_THROW(check_composite_closed(c));
  for (std::size_t p = 0; p < c.patches.size(); ++p) EXPECT_LT(boundary_residual(c, p), 1e-12);
}

/// Points on the patches of `c`: random points of its box moved onto each patch by Newton steps, kept
/// where they land inside that patch's region; for each, the number of neighbouring patches (sharing a
/// corner with it) whose region also holds it by more than `tol`. (Regions are local: a face's region
/// is a prism through the whole solid, and holds points of the opposite face.)
int overlaps(const Composite& c, double tol, int& points) {
  const auto corners = [&](std::size_t k) {
    std::vector<Vec3> out;
    for (const PatchSide& s : c.patches[k].sides)
      out.push_back(c.curves[s.curve].start), out.push_back(c.curves[s.curve].end);
    return out;
  };
  const auto neighbours = [&](std::size_t a, std::size_t b) {
    for (const Vec3& p : corners(a)) {
      for (const Vec3& q : corners(b)) {
        if (p == q) return true;
      }
    }
    return false;
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int bad = 0;
  points = 0;
  for (int i = 0; i < 1500; ++i) {
    const Vec3 start = c.box.lo + c.box.size().cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
    for (std::size_t k = 0; k < c.patches.size(); ++k) {
      Vec3 x = start;
      for (int step = 0; step < 30; ++step) {
        const ValueGradient g = c.patches[k].surface->value_gradient(x);
        if (!(g.gradient.squaredNorm() > 0.0)) break;
        x -= g.value * g.gradient / g.gradient.squaredNorm();
      }
      if (std::abs(c.patches[k].surface->value(x)) > 1e-12 || (x - start).norm() > 0.3) continue;
      const auto margin = [&](std::size_t j) {
        double m = HUGE_VAL;
        for (const auto& b : c.patches[j].bounds) m = std::min(m, b->value(x));
        return m;
      };
      if (margin(k) < tol) continue;
      ++points;
      for (std::size_t j = 0; j < c.patches.size(); ++j) {
        if (j != k && neighbours(j, k) && margin(j) > tol) ++bad;
      }
    }
  }
  return bad;
}

TEST(SetbackSolid, RegionsOfNeighboursDoNotOverlapOnTheSurface) {
  // Faces, edge blends and vertex blends share their bounding functions with opposite signs, so a
  // point of one patch lies in no other patch's region: the piecewise function is well defined there.
  SetbackSolid unequal = box(0.25, 0.6);
  unequal.vertex_setbacks.push_back({7, 0.75});
  for (const SetbackSolid& s : {box(0.3, 0.6), box(0.3, 0.6, false), unequal}) {
    int points = 0;
    EXPECT_EQ(overlaps(build_setback_solid(s), 1e-9, points), 0);
    EXPECT_GT(points, 500);
  }
}

TEST(SetbackSolid, RefusesWhatItCannotBlend) {
  EXPECT_THROW(build_setback_solid(box(0.3, 0.25)), InputError);  // springlines meet beyond the setback
  EXPECT_THROW(build_setback_solid(box(0.3, 1.1)), InputError);   // setbacks overlap on an edge
  EXPECT_THROW(build_setback_solid(box(0.0, 0.6)), InputError);
  // A nonagonal prism: its faces would have 18 sides.
  SetbackSolid prism;
  prism.radius = 0.05;
  prism.setback = 0.2;
  for (int z = 0; z < 2; ++z) {
    for (int k = 0; k < 9; ++k)
      prism.mesh.vertices.push_back({std::cos(2 * M_PI * k / 9), std::sin(2 * M_PI * k / 9), double(z)});
  }
  prism.mesh.faces.push_back({8, 7, 6, 5, 4, 3, 2, 1, 0});
  prism.mesh.faces.push_back({9, 10, 11, 12, 13, 14, 15, 16, 17});
  for (std::uint32_t i = 0; i < 9; ++i) prism.mesh.faces.push_back({i, (i + 1) % 9, (i + 1) % 9 + 9, i + 9});
  try {
    build_setback_solid(prism);
    ADD_FAILURE() << "a nonagonal prism was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a trimmed face has twice as many sides"), std::string::npos)
        << e.what();
  }
  // An L-shaped prism: one concave edge.
  SetbackSolid l;
  l.radius = 0.1;
  l.setback = 0.3;
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (int z = 0; z < 2; ++z) {
    for (const auto& p : xy) l.mesh.vertices.push_back({p[0], p[1], double(z)});
  }
  l.mesh.faces.push_back({5, 4, 3, 2, 1, 0});
  l.mesh.faces.push_back({6, 7, 8, 9, 10, 11});
  for (std::uint32_t i = 0; i < 6; ++i) l.mesh.faces.push_back({i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6});
  try {
    build_setback_solid(l);
    ADD_FAILURE() << "an L-shaped solid was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not convex"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace isopatch
