#include <isopatch/callable_surface.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "projection/ray_march.hpp"
#include "surface/bracketed_root.hpp"
#include "test_surfaces.hpp"

namespace isopatch {
namespace {

TEST(RayMarch, FindsTheFirstCrossingInsideTheRegion) {
  const auto s = test::sphere(1.0);
  const Sampler f(*s);
  const Box region{Vec3::Constant(-2), Vec3::Constant(2)};
  // From the centre (inside) along +x: the crossing at x = 1.
  const auto hit = march_to_surface(f, Vec3::Zero(), f.value(Vec3::Zero()), Vec3(1, 0, 0), region);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x(), 1.0, 1e-12);
  // From outside, the direction (towards the positive side) is reversed: from (1.5,0,0) with +x, go -x.
  const Vec3 out(1.5, 0, 0);
  const auto back = march_to_surface(f, out, f.value(out), Vec3(1, 0, 0), region);
  ASSERT_TRUE(back);
  EXPECT_NEAR(back->point.x(), 1.0, 1e-12);
  EXPECT_LT(back->ray_direction.x(), 0.0);
}

TEST(RayMarch, MissesWhenTheRegionEndsFirst) {
  const auto s = test::sphere(1.0);
  const Sampler f(*s);
  const Box region{Vec3::Constant(-0.5), Vec3::Constant(0.5)};
  EXPECT_FALSE(march_to_surface(f, Vec3::Zero(), f.value(Vec3::Zero()), Vec3(1, 0, 0), region));
}

TEST(RayMarch, RespectsPlanesAndCurvedBoundsOfItsRegion) {
  // f = x - 0.5 marched along +x; the region's bounds decide which crossings count.
  const SurfacePtr plane = make_surface([](auto x, auto, auto) { return x - 0.5; },
                                        Box{Vec3::Constant(-2), Vec3::Constant(2)}, "plane");
  const Sampler f(*plane);
  const RayMarchSettings settings;
  const auto march = [&](const Vec3& start, const Vec3& direction, const MarchRegion& region) {
    return march_to_surface(f, start, f.value(start), direction, region, settings);
  };
  // A convex cell cut by the plane x <= 0.4: the crossing at x = 0.5 lies beyond it.
  const Box box{Vec3::Constant(-1), Vec3::Constant(1)};
  const std::vector<CellPlane> cut{make_cell_plane(1, 0, 0, -0.4)};
  EXPECT_TRUE(march(Vec3::Zero(), Vec3(1, 0, 0), MarchRegion::cell(box)));
  EXPECT_FALSE(march(Vec3::Zero(), Vec3(1, 0, 0), MarchRegion::cell(box, cut)));
  // Curved bounds |y| >= 0.1 (two slabs: a concave region) with a reach of 2.
  const std::vector<SurfacePtr> bounds{make_surface([](auto, auto y, auto) { return y * y - 0.01; },
                                                    Box{Vec3::Constant(-2), Vec3::Constant(2)}, "slabs")};
  const CurvedBounds slabs(bounds, 0.0);
  const MarchRegion region = MarchRegion::curved_region(slabs, 2.0);
  // Inside all the way (y = 0.3): the crossing at (0.5, 0.3, 0) counts.
  const auto hit = march(Vec3(0, 0.3, 0), Vec3(1, 0, 0), region);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x(), 0.5, 1e-12);
  // Leaving the region (|y| < 0.1 between x = 0.2 and 0.4) and entering it again before the crossing
  // at (0.5, -0.2, 0): the march stops where it leaves, so no hit.
  EXPECT_FALSE(march(Vec3(0, 0.3, 0), Vec3(1, -1, 0), region));
  // Starting outside (y = 0.05) and never inside: the crossing at (0.5, 0.05, 0) is outside, no hit.
  EXPECT_FALSE(march(Vec3(0, 0.05, 0), Vec3(1, 0, 0), region));
  // The reach bounds the march: from x = -2 the crossing is 2.5 away.
  EXPECT_FALSE(march(Vec3(-2, 0.3, 0), Vec3(1, 0, 0), region));
}

TEST(RayMarch, ExitDistanceOfSlabs) {
  const Box box{Vec3::Zero(), Vec3::Ones()};
  EXPECT_DOUBLE_EQ(exit_distance(Vec3(0.25, 0.5, 0.5), Vec3(1, 0, 0), box), 0.75);
  EXPECT_DOUBLE_EQ(exit_distance(Vec3(0.25, 0.5, 0.5), Vec3(-1, 0, 0), box), 0.25);
}

// The batched march gives exactly what one march at a time gives, with the same evaluations: rays that
// cross once or several times (the tanglecube), that miss, that start on f = 0, a zero direction.
TEST(RayMarch, BatchedRaysMatchOneMarchAtATime) {
  const auto s = test::tanglecube();
  const Box region{Vec3::Constant(-2.5), Vec3::Constant(2.5)};
  std::vector<RayStart> rays;
  for (int i = 0; i < 200; ++i) {
    // A fixed scatter of starts and directions (no random source: the same rays on every run).
    const double a = 0.37 * i, b = 0.11 * i * i;
    const Vec3 start(2.4 * std::sin(a), 2.4 * std::cos(1.3 * a), 2.4 * std::sin(0.7 * b));
    const Vec3 direction(std::cos(b), std::sin(2.0 * a), std::cos(a + b));
    rays.push_back({start, 0.0, direction});
  }
  rays.push_back({Vec3(0.1, 0.2, 0.3), 0.0, Vec3::Zero()});
  const Sampler f(*s);
  for (RayStart& r : rays) r.f_start = f.value(r.start);
  rays.push_back({Vec3(1, 2, 2), 0.0, Vec3(1, 0, 0)});  // f_start 0 as given: a hit where it starts
  const Sampler one(*s), batched(*s);
  std::vector<std::optional<RayHit>> hits;
  march_rays(batched, rays, region, RayMarchSettings{}, hits);
  ASSERT_EQ(hits.size(), rays.size());
  int found = 0, missed = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto expected = march_to_surface(one, rays[i].start, rays[i].f_start, rays[i].direction, region);
    ASSERT_EQ(expected.has_value(), hits[i].has_value()) << "ray " << i;
    if (!expected) {
      ++missed;
      continue;
    }
    ++found;
    EXPECT_EQ(expected->point, hits[i]->point) << "ray " << i;
    EXPECT_EQ(expected->ray_direction, hits[i]->ray_direction);
    EXPECT_EQ(expected->distance, hits[i]->distance);
  }
  EXPECT_GT(found, 50);
  EXPECT_GT(missed, 1);
  EXPECT_EQ(one.value_count(), batched.value_count());
}

// The root finder's state machine: the root of cos t - 0.3 on [0, 2] to the tolerance, and no more
// evaluations than allowed.
TEST(BracketedRoot, FindsTheRootWithinItsBudget) {
  BracketedRoot root(0.0, 0.7, 2.0, std::cos(2.0) - 0.3, 1e-14);
  int evaluations = 0;
  while (!root.done()) {
    root.feed(std::cos(root.next()) - 0.3);
    ++evaluations;
  }
  EXPECT_NEAR(root.result(), std::acos(0.3), 1e-13);
  EXPECT_LT(evaluations, 20);
  BracketedRoot capped(0.0, 0.7, 2.0, std::cos(2.0) - 0.3, 0.0, 3);
  evaluations = 0;
  while (!capped.done()) {
    capped.feed(std::cos(capped.next()) - 0.3);
    ++evaluations;
  }
  EXPECT_EQ(evaluations, 3);
  EXPECT_EQ(BracketedRoot(0.5, 0.0, 1.0, 1.0, 1e-9).result(), 0.5);
}

}  // namespace
}  // namespace isopatch
