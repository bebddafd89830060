/// \file composite_checks.cpp
/// Closure checks and residuals of composites (composite_checks.hpp).
#include "composite_model/composite_checks.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace isopatch {

namespace {}  // namespace

void check_composite_closed(const Composite& composite) {
  std::vector<int> forward(composite.curves.size(), 0), backward(composite.curves.size(), 0);
  for (const CompositePatch& p : composite.patches) {
    const std::size_t n = p.sides.size();
    if (n < 3) throw InputError(p.name + ": a patch needs at least 3 sides");
    if (!p.surface) throw InputError(p.name + ": no function");
    if (p.corner_directions.size() != n) throw InputError(p.name + ": one corner direction per side needed");
    for (const Vec3& d : p.corner_directions) {
      if (!d.allFinite() || std::abs(d.norm() - 1.0) > 1e-9) {
        throw InputError(p.name + ": corner directions must be unit vectors");
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      const PatchSide& s = p.sides[k];
      if (s.curve >= composite.curves.size()) throw InputError(p.name + ": a side names no curve");
      if (side_end(composite, s) != side_start(composite, p.sides[(k + 1) % n])) {
        throw InputError(p.name + ": side " + std::to_string(k + 1) + " does not end where side " +
                         std::to_string((k + 1) % n + 1) + " starts");
      }
      (s.reversed ? backward : forward)[s.curve] += 1;
    }
  }
  for (std::size_t c = 0; c < composite.curves.size(); ++c) {
    if (forward[c] != 1 || backward[c] != 1) {
      throw InputError("curve " + std::to_string(c) + " is used " + std::to_string(forward[c]) +
                       " times forward and " + std::to_string(backward[c]) +
                       " times reversed (a closed composite uses each curve once each way)");
    }
  }
}

double boundary_residual(const Composite& composite, std::size_t patch, int samples) {
  const CompositePatch& p = composite.patches.at(patch);
  double worst = 0.0;
  for (const PatchSide& s : p.sides) {
    for (int j = 1; j <= samples; ++j) {
      const double t = static_cast<double>(j) / (samples + 1);
      const ValueGradient vg = p.surface->value_gradient(composite.curves[s.curve].point(t));
      const double g = vg.gradient.norm();
      worst = std::max(worst, g > 0.0 ? std::abs(vg.value) / g : std::abs(vg.value) > 0.0 ? HUGE_VAL : 0.0);
    }
  }
  return worst;
}

Box curves_box(const std::vector<ConicArc>& curves, const std::vector<Vec3>& extra, double margin) {
  Box box{Vec3::Constant(HUGE_VAL), Vec3::Constant(-HUGE_VAL)};
  const auto add = [&](const Vec3& p) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  };
  for (const ConicArc& a : curves) {
    add(a.start);
    add(a.control);
    add(a.end);
  }
  for (const Vec3& p : extra) add(p);
  const double grow = margin * box.diagonal();
  box.lo -= Vec3::Constant(grow);
  box.hi += Vec3::Constant(grow);
  return box;
}

void check_composite(const Composite& c) {
  std::vector<int> uses(c.curves.size(), 0);
  std::vector<int> forward(c.curves.size(), 0);
  for (const CompositePatch& p : c.patches) {
    const std::size_t n = p.sides.size();
    if (n < 3 || n > 12)
      throw InputError("patch '" + p.name + "' has " + std::to_string(n) + " sides (want 3 to 12)");
    if (p.corner_directions.size() != n)
      throw InputError("patch '" + p.name + "' has " + std::to_string(p.corner_directions.size()) +
                       " corner directions for " + std::to_string(n) + " sides");
    for (const Vec3& d : p.corner_directions)
      if (!d.allFinite() || !(d.norm() > 0.0))
        throw InputError("patch '" + p.name +
                         "' has a corner direction that is not a finite non-zero vector");
    for (const PatchSide& s : p.sides)
      if (s.curve >= c.curves.size())
        throw InputError("patch '" + p.name + "' names curve " + std::to_string(s.curve) + " of " +
                         std::to_string(c.curves.size()));
    for (std::size_t k = 0; k < n; ++k)
      if (side_end(c, p.sides[k]) != side_start(c, p.sides[(k + 1) % n]))
        throw InputError("patch '" + p.name + "': side " + std::to_string(k) + " does not end where side " +
                         std::to_string((k + 1) % n) + " starts");
    for (const PatchSide& s : p.sides) {
      ++uses[s.curve];
      if (!s.reversed) ++forward[s.curve];
    }
  }
  for (std::size_t i = 0; i < c.curves.size(); ++i) {
    if (uses[i] > 2)
      throw InputError("curve " + std::to_string(i) + " bounds " + std::to_string(uses[i]) +
                       " patch sides (at most 2)");
    if (uses[i] == 2 && forward[i] != 1)
      throw InputError("curve " + std::to_string(i) +
                       " is used twice in the same direction (the patches are not oriented consistently)");
  }
}

}  // namespace isopatch
