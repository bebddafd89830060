// Cancellation through Settings::cancel raised from the first Settings::progress report (as a UI
// would): mesh_surface stops with LimitError("cancelled") for both methods, having done only a small
// part of the work of a full run (counted in evaluations of f, so the test does not depend on the
// machine's speed).
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

namespace isopatch {
namespace {

/// Delegates to another surface and counts every evaluation (values, gradients, bounds).
class CountingSurface : public Surface {
 public:
  explicit CountingSurface(SurfacePtr inner)
      : Surface(inner->name(), inner->box()), inner_(std::move(inner)) {}

  double value(const Vec3& p) const override {
    ++count_;
    return inner_->value(p);
  }
  void values(std::span<const Vec3> points, std::span<double> out) const override {
    count_ += points.size();
    inner_->values(points, out);
  }
  ValueGradient value_gradient(const Vec3& p) const override {
    ++count_;
    return inner_->value_gradient(p);
  }
  SecondOrder second_order(const Vec3& p) const override {
    ++count_;
    return inner_->second_order(p);
  }
  std::optional<Interval> bound(const Box& box) const override {
    ++count_;
    return inner_->bound(box);
  }
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override {
    ++count_;
    return inner_->gradient_bound(box);
  }

  std::uint64_t count() const { return count_.load(); }

 private:
  SurfacePtr inner_;
  mutable std::atomic<std::uint64_t> count_{0};
};

Settings sized(Method method) {
  Settings s;
  s.method = method;
  s.grid = 96;
  s.edge_length = 3.2 / 64.0;  // the torus box's longest side / 64
  return s;
}

TEST(Cancellation, RaisedFromTheFirstProgressReportStopsBothMethodsEarly) {
  for (Method method : {Method::MarchingCubes, Method::Projection}) {
    SCOPED_TRACE(method_name(method));
    const CountingSurface full_run(catalogue_surface("torus"));
    ASSERT_GT(mesh_surface(full_run, sized(method)).vertex_count(), 0u);

    const CountingSurface surface(catalogue_surface("torus"));
    std::atomic<bool> cancel{false};
    int reports = 0;
    Settings settings = sized(method);
    settings.cancel = &cancel;
    settings.progress = [&](const Progress&) {
      ++reports;
      cancel = true;
    };
    try {
      mesh_surface(surface, settings);
      ADD_FAILURE() << "not cancelled";
    } catch (const LimitError& e) {
      EXPECT_STREQ(e.what(), "cancelled");
    }
    EXPECT_EQ(reports, 1);  // no work reported after the cancel
    // Marching cubes stops after its first slab (of 36); projection after its first partition build.
    EXPECT_LT(surface.count(), full_run.count() / (method == Method::MarchingCubes ? 10 : 3))
        << surface.count() << " evaluations when cancelled, " << full_run.count() << " in a full run";
    RecordProperty(
        method_name(method) + "_cancelled_share",
        std::to_string(static_cast<double>(surface.count()) / static_cast<double>(full_run.count())));
  }
}

}  // namespace
}  // namespace isopatch
