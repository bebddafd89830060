// Interval pruning, input validation, evaluation errors and cancellation of build_partition.
#include "partition/partition.hpp"
#include "partition_checks.hpp"
#include "test_surfaces.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>

namespace isopatch {
namespace {

// A sphere with exact interval bounds of f and of its gradient over boxes (rounding covered by a
// small widening). Its value is computed in the same order as test::sphere, so both give the same bits.
class BoundedSphere final : public Surface {
 public:
  BoundedSphere(double radius, const Vec3& centre)
      : Surface("bounded_sphere", Box{centre - Vec3::Constant(1.2), centre + Vec3::Constant(1.2)}),
        r_(radius),
        c_(centre) {}

  double value(const Vec3& p) const override {
    const double x = p.x(), y = p.y(), z = p.z();
    return (x - c_.x()) * (x - c_.x()) + (y - c_.y()) * (y - c_.y()) + (z - c_.z()) * (z - c_.z()) - r_ * r_;
  }
  ValueGradient value_gradient(const Vec3& p) const override { return {value(p), 2.0 * (p - c_)}; }
  SecondOrder second_order(const Vec3& p) const override {
    return {value(p), 2.0 * (p - c_), 2.0 * Mat3::Identity()};
  }
  std::optional<Interval> bound(const Box& box) const override {
    double lo = -r_ * r_, hi = -r_ * r_;
    for (int a = 0; a < 3; ++a) {
      const double u = box.lo[a] - c_[a], v = box.hi[a] - c_[a];
      hi += std::max(u * u, v * v);
      if (u > 0.0 || v < 0.0) lo += std::min(u * u, v * v);
    }
    const double slack = 1e-12 * (std::abs(lo) + std::abs(hi) + r_ * r_);
    return Interval{lo - slack, hi + slack};
  }
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override {
    IntervalGradient g;
    g.value = *bound(box);
    for (int a = 0; a < 3; ++a)
      g.gradient[a] = Interval{2.0 * (box.lo[a] - c_[a]), 2.0 * (box.hi[a] - c_[a])};
    return g;
  }

 private:
  double r_;
  Vec3 c_;
};

// NaN wherever x > 0.3, a sphere elsewhere.
class PartlyNan final : public Surface {
 public:
  PartlyNan() : Surface("partly_nan", Box{Vec3::Constant(-1.2), Vec3::Constant(1.2)}) {}
  double value(const Vec3& p) const override {
    return p.x() > 0.3 ? std::numeric_limits<double>::quiet_NaN() : p.squaredNorm() - 1.0;
  }
  ValueGradient value_gradient(const Vec3& p) const override { return {value(p), 2.0 * p}; }
  SecondOrder second_order(const Vec3& p) const override {
    return {value(p), 2.0 * p, 2.0 * Mat3::Identity()};
  }
};

// A ball with a thin needle along +x (distance fields, union by min), whose gradient is reported 1000
// times too small: the heuristic empty test then prunes coarse cells that the needle crosses between
// their corners and centres. The needle's axis is one fine lattice step off the coarse lattice lines.
class ShyNeedle final : public Surface {
 public:
  ShyNeedle(const Vec3& centre, double fine_step)
      : Surface("shy_needle", Box{Vec3::Constant(-1.0), Vec3::Constant(1.0)}),
        c_(centre),
        axis_(centre + Vec3(0.0, fine_step, fine_step)) {}
  double value(const Vec3& p) const override { return std::min(ball(p), needle(p)); }
  ValueGradient value_gradient(const Vec3& p) const override {
    const Vec3 g = ball(p) <= needle(p) ? (p - c_).normalized() : (p - closest(p)).normalized();
    return {value(p), 1e-3 * g};
  }
  SecondOrder second_order(const Vec3& p) const override {
    const ValueGradient vg = value_gradient(p);
    return {vg.value, vg.gradient, Mat3::Zero()};
  }

 private:
  double ball(const Vec3& p) const { return (p - c_).norm() - 0.3; }
  Vec3 closest(const Vec3& p) const {
    return axis_ + Vec3(std::clamp(p.x() - axis_.x(), 0.0, 0.85), 0.0, 0.0);
  }
  double needle(const Vec3& p) const { return (p - closest(p)).norm() - 0.05; }

  Vec3 c_;
  Vec3 axis_;
};

TEST(PartitionHeuristic, WrongPrunesAreRepairedAlongTheCrossings) {
  PartitionSettings settings;
  settings.surface_depth = 4;
  settings.max_depth = 5;
  const Box box{Vec3::Constant(-1.0), Vec3::Constant(1.0)};
  const Lattice lattice = make_lattice(box, settings.max_depth);
  const ShyNeedle surface(lattice.cell_box(1, {1, 1, 1}).lo, lattice.unit() * lattice.step(4));
  const Partition p = build_partition(surface, box, settings);
  EXPECT_GT(p.stats.pruned_by_heuristic, 0u);
  EXPECT_GT(p.stats.cells_recovered, 0u);
  test::expect_partition_invariants(surface, p);
}

TEST(PartitionIntervals, PruneSoundlyAndSaveEvaluations) {
  const Vec3 centre(0.1, -0.2, 0.05);
  const BoundedSphere bounded(0.8, centre);
  const auto plain = test::sphere(0.8, centre, 1.2);
  PartitionSettings settings;
  settings.surface_depth = 5;
  settings.max_depth = 6;
  const Partition a = build_partition(bounded, bounded.box(), settings);
  const Partition b = build_partition(*plain, plain->box(), settings);
  test::expect_partition_invariants(bounded, a);

  EXPECT_GT(a.stats.pruned_by_interval, 0u);
  EXPECT_EQ(a.stats.pruned_by_heuristic, 0u);
  EXPECT_GT(a.stats.edges_certified_by_interval, 0u);
  EXPECT_EQ(b.stats.pruned_by_interval, 0u);
  EXPECT_GT(b.stats.pruned_by_heuristic, 0u);
  EXPECT_LT(a.stats.value_evaluations, b.stats.value_evaluations);
  EXPECT_LT(a.stats.gradient_evaluations, b.stats.gradient_evaluations);

  // Same leaves, same verdicts, same corners.
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  for (std::size_t i = 0; i < a.leaves.size(); ++i) {
    EXPECT_EQ(a.leaves[i].coords, b.leaves[i].coords);
    EXPECT_EQ(a.leaves[i].kind, b.leaves[i].kind);
  }
  ASSERT_EQ(a.crossings.size(), b.crossings.size());
  for (std::size_t i = 0; i < a.crossings.size(); ++i) {
    EXPECT_EQ(a.crossings[i].segment, b.crossings[i].segment);
    EXPECT_EQ(a.crossings[i].position, b.crossings[i].position);
  }

  settings.use_intervals = false;
  const Partition c = build_partition(bounded, bounded.box(), settings);
  EXPECT_EQ(c.stats.pruned_by_interval, 0u);
  EXPECT_EQ(c.stats.interval_evaluations, 0u);
  EXPECT_EQ(c.leaves.size(), a.leaves.size());
}

TEST(PartitionErrors, NanSurfaceThrowsEvaluationError) {
  const PartlyNan surface;
  try {
    build_partition(surface, surface.box(), PartitionSettings{});
    FAIL() << "no exception";
  } catch (const EvaluationError& e) {
    EXPECT_NE(std::string(e.what()).find("NaN"), std::string::npos) << e.what();
  }
}

TEST(PartitionErrors, SettingsOutOfRangeThrowInputError) {
  const auto surface = test::sphere();
  const Box box = surface->box();
  auto with = [](auto change) {
    PartitionSettings s;
    change(s);
    return s;
  };
  EXPECT_THROW(build_partition(*surface, box, with([](auto& s) { s.surface_depth = -1; })), InputError);
  EXPECT_THROW(build_partition(*surface, box, with([](auto& s) { s.surface_depth = 8; })), InputError);
  EXPECT_THROW(build_partition(*surface, box, with([](auto& s) { s.max_depth = 21; })), InputError);
  EXPECT_THROW(build_partition(*surface, box, with([](auto& s) { s.edge_samples = -1; })), InputError);
  EXPECT_THROW(build_partition(*surface, box, with([](auto& s) { s.cone_angle_deg = 0.0; })), InputError);
  EXPECT_THROW(build_partition(*surface, box, with([](auto& s) { s.cone_angle_deg = 91.0; })), InputError);
  EXPECT_THROW(build_partition(*surface, Box{Vec3::Zero(), Vec3(1, 1, 0)}, PartitionSettings{}), InputError);
}

TEST(PartitionErrors, CancelledBuildThrowsLimitError) {
  const auto surface = test::sphere();
  const std::atomic<bool> cancel{true};
  PartitionSettings settings;
  settings.cancel = &cancel;
  EXPECT_THROW(build_partition(*surface, surface->box(), settings), LimitError);
}

// Loosening the tests can only turn Complex leaves into Simple ones; the leaves themselves (which
// depend only on signs and the empty tests) stay.
TEST(PartitionTests, DisablingTestsKeepsLeavesAndMakesMoreSimple) {
  const auto surface = test::tanglecube();
  PartitionSettings strict;
  strict.surface_depth = 4;
  strict.max_depth = 5;
  strict.cone_angle_deg = 40.0;
  PartitionSettings loose = strict;
  loose.cone_angle_deg = 90.0;
  loose.face_test = false;
  const Partition a = build_partition(*surface, surface->box(), strict);
  const Partition b = build_partition(*surface, surface->box(), loose);
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  EXPECT_GT(a.stats.complex_by_reason[static_cast<int>(ComplexReason::NormalCone)], 0u);
  EXPECT_GT(b.stats.simple_leaves, a.stats.simple_leaves);
  for (std::size_t i = 0; i < a.leaves.size(); ++i)
    if (a.leaves[i].kind == LeafKind::Simple) {
      EXPECT_EQ(b.leaves[i].kind, LeafKind::Simple);
    }
}

TEST(PartitionSettings, DepthZeroMakesTheRootCubeTheOnlyCell) {
  // A sphere clipped by the unit cube around one corner: one leaf, one triangle loop.
  const auto surface = make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z - 0.36; },
                                    Box{Vec3::Zero(), Vec3::Ones()});
  PartitionSettings s;
  s.surface_depth = 0;
  s.max_depth = 0;
  const Partition p = build_partition(*surface, surface->box(), s);
  ASSERT_EQ(p.leaves.size(), 1u);
  ASSERT_EQ(p.leaves[0].loops.size(), 1u);
  EXPECT_EQ(p.leaves[0].loops[0].corners.size(), 3u);
}

}  // namespace
}  // namespace isopatch
