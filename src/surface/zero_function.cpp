// f identically zero on the box: see zero_function.hpp.
#include "surface/zero_function.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace isopatch {
namespace {

/// Fractions of a sample cell by which the samples are shifted (no dyadic components).
const Vec3 kShift(0.1234, 0.5678, 0.9012);

bool exactly_zero(const ValueGradient& vg) {
  return vg.value == 0.0 && vg.gradient[0] == 0.0 && vg.gradient[1] == 0.0 && vg.gradient[2] == 0.0;
}

}  // namespace

ZeroEvidence zero_function_evidence(const Surface& surface, const Box& box) {
  if (const std::optional<Interval> bound = surface.bound(box); bound && bound->lo == 0.0 && bound->hi == 0.0)
    return ZeroEvidence::Interval;
  const Vec3 step = box.size() / kZeroCheckSamples;
  for (int k = 0; k < kZeroCheckSamples; ++k)
    for (int j = 0; j < kZeroCheckSamples; ++j)
      for (int i = 0; i < kZeroCheckSamples; ++i) {
        const Vec3 index(i, j, k);
        const Vec3 p = box.lo + (index + kShift).cwiseProduct(step);
        if (!exactly_zero(surface.value_gradient(p))) return ZeroEvidence::None;  // NaN compares unequal
      }
  return ZeroEvidence::Samples;
}

void reject_zero_function(const Surface& surface, const Box& box) {
  if (!box.valid()) return;
  const ZeroEvidence evidence = zero_function_evidence(surface, box);
  if (evidence == ZeroEvidence::None) return;
  const int n = kZeroCheckSamples;
  const std::string why = evidence == ZeroEvidence::Interval
                              ? "its interval bound over the box is [0, 0]"
                              : "f and grad f are 0 at all " + std::to_string(n * n * n) + " sample points";
  throw NoSurfaceError("no surface in the box " + format_box(box) + ": f is identically zero there (" + why +
                       "), so f = 0 is the whole box, not a surface");
}

}  // namespace isopatch
