// grad f vanishing on f = 0: see singular_level_set.hpp.
#include "surface/singular_level_set.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "surface/bracketed_root.hpp"
#include "surface/sign_rule.hpp"

namespace isopatch {
namespace {

/// Fractions of a sample cell by which the samples are shifted (no dyadic components; not those of the
/// zero-function check, so the two grids differ).
const Vec3 kCrossingShift(0.3141, 0.2718, 0.1618);
/// |grad f| below this fraction of the slope of f across the crossing is singular.
constexpr double kSingularSlope = 1e-3;
/// Fewer examined crossings than this give no verdict.
constexpr std::size_t kMinRoots = 8;

struct GridEdge {
  Vec3 a;
  double fa;
  Vec3 b;
  double fb;
};

/// Whether the crossing of f = 0 on `e` (f of opposite signs at its ends) is singular; sets *root.
bool singular_crossing(const Surface& surface, const GridEdge& e, Vec3* root) {
  const Vec3 d = e.b - e.a;
  const double length = d.norm();
  const Vec3 unit = d / length;
  const auto phi = [&](double t) { return surface.value(e.a + t * unit); };
  const double t = bracketed_root(phi, 0.0, e.fa, length, e.fb, 1e-12 * length, 200);
  *root = e.a + t * unit;
  const double h = 0.25 * length;
  const double slope =
      std::abs(surface.value(*root + h * unit) - surface.value(*root - h * unit)) / (2.0 * h);
  const double gradient = surface.value_gradient(*root).gradient.norm();
  if (!(std::isfinite(slope) && std::isfinite(gradient)) || !(slope > 0.0)) return false;
  return gradient < kSingularSlope * slope;
}

/// p with coordinates below 1e-9 of the box's size shown as 0 (a root found to rounding).
std::string format_example(const Vec3& p, const Box& box) {
  const double tiny = 1e-9 * box.size().maxCoeff();
  const auto shown = [&](double c) { return std::abs(c) < tiny ? 0.0 : c; };
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", shown(p.x()), shown(p.y()), shown(p.z()));
  return text;
}

}  // namespace

SingularEvidence singular_level_set_evidence(const Surface& surface, const Box& box) {
  constexpr int n = kSingularCheckSamples;
  const Vec3 step = box.size() / n;
  const auto point = [&](int i, int j, int k) {
    return Vec3(box.lo + (Vec3(i, j, k) + kCrossingShift).cwiseProduct(step));
  };
  std::vector<double> values(static_cast<std::size_t>(n * n * n));
  const auto at = [&](int i, int j, int k) -> double& {
    return values[static_cast<std::size_t>((k * n + j) * n + i)];
  };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) at(i, j, k) = surface.value(point(i, j, k));
  std::vector<GridEdge> crossings;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double v = at(i, j, k);
        if (!std::isfinite(v)) continue;
        const int next[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
        for (const auto& q : next) {
          if (q[0] >= n || q[1] >= n || q[2] >= n) continue;
          const double w = at(q[0], q[1], q[2]);
          if (std::isfinite(w) && is_negative(v) != is_negative(w))
            crossings.push_back({point(i, j, k), v, point(q[0], q[1], q[2]), w});
        }
      }
  SingularEvidence evidence;
  if (crossings.empty()) return evidence;
  const std::size_t stride = (crossings.size() + kSingularCheckRoots - 1) / kSingularCheckRoots;
  for (std::size_t c = 0; c < crossings.size(); c += stride) {
    Vec3 root;
    const bool singular = singular_crossing(surface, crossings[c], &root);
    ++evidence.roots;
    if (singular && evidence.singular++ == 0) evidence.example = root;
  }
  return evidence;
}

void reject_singular_level_set(const Surface& surface, const Box& box) {
  if (!box.valid()) return;
  const SingularEvidence e = singular_level_set_evidence(surface, box);
  if (e.roots < kMinRoots || static_cast<double>(e.singular) < kSingularShare * static_cast<double>(e.roots))
    return;
  const long percent = std::lround(100.0 * static_cast<double>(e.singular) / static_cast<double>(e.roots));
  throw SingularSurfaceError("grad f vanishes on f = 0 at " + std::to_string(percent) + "% of " +
                             std::to_string(e.roots) + " sampled surface points (e.g. " +
                             format_example(e.example, box) +
                             "): a repeated factor such as g^3? Mesh g instead (projection needs grad f)");
}

}  // namespace isopatch
