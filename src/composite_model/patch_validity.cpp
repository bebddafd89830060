/// \file patch_validity.cpp
/// Root counting along lines through each I-patch's region (patch_validity.hpp).
#include "composite_model/patch_validity.hpp"

#include "composite_model/ipatch_surface.hpp"
#include "composite_model/quadric.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace isopatch {

namespace {

/// Below this length the sum of the corner directions (normals of length about 1) counts as cancelled:
/// no direction leans toward them all. Far above the rounding of such a sum, far below any real lean.
constexpr double kValidityCancelledSum = 1e-9;
/// First step (in radians, roughly) of central_direction's subgradient ascent: a quarter radian lets it
/// cross a large part of the sphere early when the normalized sum starts far from the optimum.
constexpr double kValidityAscentFirstStep = 0.25;
/// Steps of the ascent, each shrunk by kValidityAscentShrink: 200 steps of 0.25 * 0.97^k add up to about
/// 8.3 radians (any start can reach the optimum) and end at 5.7e-4 (0.03 degrees), finer than the lines
/// need: they only have to lean toward every corner direction. Chosen empirically, cheap beside the check.
constexpr int kValidityAscentIterations = 200;
constexpr double kValidityAscentShrink = 0.97;
/// Parameter intervals per side when only the extent (size, box of the lines) of the boundary is wanted:
/// on a circular arc of up to a half-turn the samples miss at most 1 - cos(pi/32), 0.5% of its radius,
/// which kValidityExtentMargin covers; more samples would only refine a box that is widened anyway.
constexpr int kValidityExtentSegments = 16;
constexpr double kValidityExtentSegmentsD = kValidityExtentSegments;  ///< the same, as the divisor of t
/// The lines' grid is widened by this fraction of the size on every side, so that a patch bulging a
/// little past its boundary's footprint is still crossed; costs a few lines that miss the region.
constexpr double kValidityExtentMargin = 0.05;
/// How far (in sizes) the lines run below and above the boundary's extent along the central direction, as
/// the patch may sag or rise: a hemispherical cap rises half its boundary's diameter, more than a one-sheet
/// patch leaning toward its corner directions should (longer lines would only spread the steps thinner).
constexpr double kValiditySagAllowance = 0.5;
/// Floors of ValidityOptions::lines_per_axis and steps_per_line, against nonsense options (no line: the
/// patch would read as unchecked; no step: t / steps divides by zero); the smallest grid and march that
/// still mean something, chosen empirically (the defaults are 20 and 240).
constexpr int kValidityMinLinesPerAxis = 2;
constexpr int kValidityMinStepsPerLine = 8;
/// Halvings of a crossing before the bulge is read: a step is at most 0.27 of the size (2.1 sizes over
/// at least 8 steps), 2^-30 of it is ~1e-9 of the size, far below bulge_tolerance (1e-3).
constexpr int kValidityBulgeBisections = 30;
/// measure_boundary_bend samples each side at t = k / 8, k = 1 ... 7 (patch_validity.hpp): the corners
/// are left out, as F is 0/0 where two bounding surfaces meet; 7 points catch a fold along part of a side
/// (chosen empirically: every fold of the examples shows at them).
constexpr int kValidityBendSegments = 8;
constexpr double kValidityBendSegmentsD = kValidityBendSegments;  ///< the same, as the divisor of t
/// Parameter step of the central difference for a side's tangent: only its direction is used, so the
/// O(dt^2) error (1e-8) and the rounding (about 1e-12 relative) are both negligible; t +- dt stays in [0, 1].
constexpr double kValidityTangentStep = 1e-4;
/// The root of the patch is sought within this many step lengths (delta) either side of the stepped
/// point along the ribbon's normal: no root within reach means the patch turned away from its ribbon
/// faster than atan(2), 63 degrees, which is a fold (docs/ipatch.md).
constexpr double kValidityRootReach = 2.0;
constexpr double kValidityRootWindow = 2 * kValidityRootReach;  ///< the whole window, -reach ... reach
/// Sign samples across that window: 32 intervals of delta / 8 separate the roots a sharp bend can put
/// close together, so the nearest one is found; chosen empirically.
constexpr int kValidityRootSearchSteps = 32;
/// Halvings of a bracketed root along the ribbon's normal: 2^-40 of delta / 8, far finer than the
/// gradients of F and the ribbon need to be placed for the angle; a few crossings per sample, so cheap.
constexpr int kValidityBendBisections = 40;
/// The angle reported where no root of the patch lies within reach: the largest angle there is, so that
/// such a sample ranks above every measured bend and beyond any fold threshold.
constexpr double kValidityNoRootAngle = 180.0;
/// measure_boundary_exit samples each side at t = k / 16, k = 1 ... 15 (patch_validity.hpp); the corners,
/// which lie on the neighbouring sides' bounds, are left out. Chosen empirically: an exit of a curve
/// through a bound spans a stretch of the side (0.041 beyond in the refused pyramid), not a point.
constexpr int kValidityExitSegments = 16;
constexpr double kValidityExitSegmentsD = kValidityExitSegments;  ///< the same, as the divisor of t
/// Floor of |grad B_j| in the distance B_j / |grad B_j|: only keeps a vanishing gradient from dividing
/// by zero; any real gradient is far larger, so the distance is unchanged.
constexpr double kValidityGradientFloor = 1e-300;
/// A side counts as leaving another side's bound when it runs outside it by more than this fraction of
/// the size (patch_validity.hpp): far above the rounding of B_j / |grad B_j| on curves that touch a bound,
/// far below a real exit (the refused pyramid's trimlines run 0.041 beyond, docs/ipatch.md).
constexpr double kValidityExitTolerance = 1e-9;

/// The planar ribbons of a patch (for the bulge test).
std::vector<const QuadricSurface*> planar_ribbons(const IPatchSurface& s) {
  std::vector<const QuadricSurface*> out;
  for (const auto& r : s.ribbons()) {
    const auto* q = dynamic_cast<const QuadricSurface*>(r.get());
    if (q && q->quadric().a.isZero(0.0)) out.push_back(q);
  }
  return out;
}

}  // namespace

Vec3 central_direction(const std::vector<Vec3>& directions) {
  Vec3 d = Vec3::Zero();
  for (const Vec3& n : directions) d += n;
  if (!(d.norm() > kValidityCancelledSum)) return Vec3::Constant(std::nan(""));
  d.normalize();
  // Subgradient ascent on min_k n_k.d over the unit sphere, with a shrinking step: the direction as
  // far as possible from every corner direction's horizon.
  double step = kValidityAscentFirstStep;
  for (int iteration = 0; iteration < kValidityAscentIterations; ++iteration, step *= kValidityAscentShrink) {
    std::size_t worst = 0;
    for (std::size_t k = 1; k < directions.size(); ++k) {
      if (directions[k].dot(d) < directions[worst].dot(d)) worst = k;
    }
    const Vec3 next = (d + step * directions[worst]).normalized();
    double before = HUGE_VAL, after = HUGE_VAL;
    for (const Vec3& n : directions) {
      before = std::min(before, n.dot(d));
      after = std::min(after, n.dot(next));
    }
    if (after > before) d = next;
  }
  return d;
}

PatchShape measure_patch(const Composite& composite, std::size_t index, const ValidityOptions& options) {
  PatchShape shape;
  const CompositePatch& patch = composite.patches.at(index);
  const auto* ip = dynamic_cast<const IPatchSurface*>(patch.surface.get());
  if (!ip) return shape;
  const Vec3 m = central_direction(patch.corner_directions);
  if (!m.allFinite()) return shape;
  const Vec3 e1 = m.unitOrthogonal(), e2 = m.cross(e1);
  // The extent of the boundary, in the frame (e1, e2, m).
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (const PatchSide& s : patch.sides) {
    for (int j = 0; j <= kValidityExtentSegments; ++j) {
      const Vec3 x = composite.curves[s.curve].point(j / kValidityExtentSegmentsD);
      const Vec3 local(x.dot(e1), x.dot(e2), x.dot(m));
      lo = lo.cwiseMin(local);
      hi = hi.cwiseMax(local);
    }
  }
  shape.size = (hi - lo).norm();
  lo -= Vec3::Constant(kValidityExtentMargin * shape.size);
  hi += Vec3::Constant(kValidityExtentMargin * shape.size);
  lo.z() -= kValiditySagAllowance * shape.size;  // the patch may sag below or rise above its boundary
  hi.z() += kValiditySagAllowance * shape.size;
  const auto planes = planar_ribbons(*ip);
  const int k = std::max(kValidityMinLinesPerAxis, options.lines_per_axis),
            steps = std::max(kValidityMinStepsPerLine, options.steps_per_line);
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) {
      const double u = lo.x() + (hi.x() - lo.x()) * (a + 0.5) / k;
      const double v = lo.y() + (hi.y() - lo.y()) * (b + 0.5) / k;
      int roots = 0;
      bool have = false;
      double previous = 0.0;
      Vec3 previous_point = Vec3::Zero();
      for (int t = 0; t <= steps; ++t) {
        const double h = lo.z() + (hi.z() - lo.z()) * t / steps;
        const Vec3 x = u * e1 + v * e2 + h * m;
        if (ip->region_margin(x) < 0.0) {
          have = false;
          continue;
        }
        const double f = ip->value(x);
        if (have && (f > 0.0) != (previous > 0.0)) {
          ++roots;
          if (!planes.empty()) {
            // Bisect the crossing, so that the bulge is measured on the patch, not a step away.
            Vec3 below = previous_point, above = x;
            const bool below_positive = previous > 0.0;
            for (int halving = 0; halving < kValidityBulgeBisections; ++halving) {
              const Vec3 mid = 0.5 * (below + above);
              ((ip->value(mid) > 0.0) == below_positive ? below : above) = mid;
            }
            for (const auto* q : planes) shape.bulge = std::max(shape.bulge, q->value(0.5 * (below + above)));
          }
        }
        previous = f;
        previous_point = x;
        have = true;
      }
      ++shape.lines;
      shape.most_roots = std::max(shape.most_roots, roots);
      if (roots > 1) ++shape.multi_root_lines;
    }
  }
  return shape;
}

BoundaryBend measure_boundary_bend(const Composite& composite, std::size_t index, double step_fraction) {
  BoundaryBend bend;
  const CompositePatch& patch = composite.patches.at(index);
  const auto* ip = dynamic_cast<const IPatchSurface*>(patch.surface.get());
  if (!ip || ip->sides() != patch.sides.size()) return bend;
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (const PatchSide& s : patch.sides) {
    for (int j = 0; j <= kValidityExtentSegments; ++j) {
      const Vec3 x = composite.curves[s.curve].point(j / kValidityExtentSegmentsD);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  }
  const double size = (hi - lo).norm();
  const auto angle = [](const Vec3& a, const Vec3& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi;
  };
  for (std::size_t i = 0; i < patch.sides.size(); ++i) {
    const ConicArc& curve = composite.curves[patch.sides[i].curve];
    const Surface& ribbon = *ip->ribbons()[i];
    const Surface& bound = *ip->bounds()[i];
    for (int k = 1; k < kValidityBendSegments; ++k) {
      const double t = k / kValidityBendSegmentsD, dt = kValidityTangentStep;
      const Vec3 p0 = curve.point(t);
      const Vec3 tangent = curve.point(t + dt) - curve.point(t - dt);
      const Vec3 normal = ribbon.value_gradient(p0).gradient;
      Vec3 inward = normal.cross(tangent);
      if (!(inward.norm() > 0.0) || !(normal.norm() > 0.0)) continue;
      inward.normalize();
      if (bound.value_gradient(p0).gradient.dot(inward) < 0.0) inward = -inward;
      const Vec3 nr = normal.normalized();
      {
        const double delta = step_fraction * size;
        const Vec3 q = p0 + delta * inward;
        // The root of F on q + s nr, s in [-2 delta, 2 delta], nearest to s = 0.
        double best = HUGE_VAL;
        Vec3 root = q;
        double previous = ip->value(q - kValidityRootReach * delta * nr);
        for (int j = 1; j <= kValidityRootSearchSteps; ++j) {
          const double s0 =
              -kValidityRootReach * delta + kValidityRootWindow * delta * (j - 1) / kValidityRootSearchSteps;
          const double s1 =
              -kValidityRootReach * delta + kValidityRootWindow * delta * j / kValidityRootSearchSteps;
          const double value = ip->value(q + s1 * nr);
          if ((value > 0.0) != (previous > 0.0)) {
            double a = s0, b = s1;
            const bool a_positive = previous > 0.0;
            for (int halving = 0; halving < kValidityBendBisections; ++halving) {
              const double mid = 0.5 * (a + b);
              ((ip->value(q + mid * nr) > 0.0) == a_positive ? a : b) = mid;
            }
            const double s = 0.5 * (a + b);
            if (std::abs(s) < std::abs(best)) {
              best = s;
              root = q + s * nr;
            }
          }
          previous = value;
        }
        const double a = std::isfinite(best)
                             ? angle(ip->value_gradient(root).gradient, ribbon.value_gradient(root).gradient)
                             : kValidityNoRootAngle;
        if (!std::isfinite(best)) ++bend.missing;
        if (a > bend.worst_angle) {
          bend.worst_angle = a;
          bend.distance = delta;
          bend.side = i;
        }
      }
    }
  }
  return bend;
}

BoundaryExit measure_boundary_exit(const Composite& composite, const CompositePatch& patch) {
  BoundaryExit worst;
  const std::size_t n = patch.sides.size();
  if (patch.bounds.size() != n) return worst;
  for (std::size_t i = 0; i < n; ++i) {
    const ConicArc& curve = composite.curves.at(patch.sides[i].curve);
    for (int k = 1; k < kValidityExitSegments; ++k) {
      const Vec3 x = curve.point(k / kValidityExitSegmentsD);
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        const ValueGradient b = patch.bounds[j]->value_gradient(x);
        const double outside = -b.value / std::max(b.gradient.norm(), kValidityGradientFloor);
        if (outside > worst.distance) worst = {outside, i, j};
      }
    }
  }
  return worst;
}

std::vector<PatchFinding> check_patch_validity(const Composite& composite, const ValidityOptions& options) {
  std::vector<PatchFinding> findings;
  for (std::size_t p = 0; p < composite.patches.size(); ++p) {
    const CompositePatch& patch = composite.patches[p];
    if (!dynamic_cast<const IPatchSurface*>(patch.surface.get())) continue;
    const PatchShape shape = measure_patch(composite, p, options);
    if (shape.lines == 0) {
      findings.push_back({p, patch.name + ": its corner directions cancel out; not checked"});
      continue;
    }
    if (shape.multi_root_lines > 0) {
      std::ostringstream out;
      out << patch.name << ": " << shape.multi_root_lines << " of " << shape.lines
          << " lines meet it more than once in its region (up to " << shape.most_roots
          << " times): extra sheets";
      findings.push_back({p, out.str()});
    }
    if (shape.bulge > options.bulge_tolerance * shape.size) {
      std::ostringstream out;
      out << patch.name << ": rises " << shape.bulge << " above a face plane it should stay below (size "
          << shape.size << ")";
      findings.push_back({p, out.str()});
    }
    const BoundaryExit exit = measure_boundary_exit(composite, patch);
    if (exit.distance > kValidityExitTolerance * shape.size) {
      std::ostringstream out;
      out << patch.name << ": side " << exit.side + 1 << " runs " << exit.distance
          << " outside the bounding surface of side " << exit.bound + 1
          << ", so the patch cannot reach its own boundary there (for a vertex blend: a setback too short "
             "for the blend radii at this vertex)";
      findings.push_back({p, out.str()});
    }
    const BoundaryBend bend = measure_boundary_bend(composite, p);
    if (bend.worst_angle > options.fold_angle) {
      std::ostringstream out;
      out << patch.name << ": folds beside side " << bend.side + 1 << ": ";
      if (bend.missing > 0) {
        out << "no point of the patch near its ribbon at " << bend.missing << " samples";
      } else {
        out << "its normal turns " << bend.worst_angle << " degrees from its ribbon's within "
            << bend.distance;
      }
      out << " (size " << shape.size << ")";
      findings.push_back({p, out.str()});
    }
  }
  return findings;
}

}  // namespace isopatch
