/// \file patch_validity.cpp
/// Root counting along lines through each I-patch's region (patch_validity.hpp).
#include "ipatch/patch_validity.hpp"

#include "ipatch/ipatch_surface.hpp"
#include "ipatch/quadric.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace isopatch {

namespace {

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
  if (!(d.norm() > 1e-9)) return Vec3::Constant(std::nan(""));
  d.normalize();
  // Subgradient ascent on min_k n_k.d over the unit sphere, with a shrinking step: the direction as
  // far as possible from every corner direction's horizon.
  double step = 0.25;
  for (int iteration = 0; iteration < 200; ++iteration, step *= 0.97) {
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
    for (int j = 0; j <= 16; ++j) {
      const Vec3 x = composite.curves[s.curve].point(j / 16.0);
      const Vec3 local(x.dot(e1), x.dot(e2), x.dot(m));
      lo = lo.cwiseMin(local);
      hi = hi.cwiseMax(local);
    }
  }
  shape.size = (hi - lo).norm();
  lo -= Vec3::Constant(0.05 * shape.size);
  hi += Vec3::Constant(0.05 * shape.size);
  lo.z() -= 0.5 * shape.size;  // the patch may sag below or rise above its boundary
  hi.z() += 0.5 * shape.size;
  const auto planes = planar_ribbons(*ip);
  const int k = std::max(2, options.lines_per_axis), steps = std::max(8, options.steps_per_line);
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
            for (int halving = 0; halving < 30; ++halving) {
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
    for (int j = 0; j <= 16; ++j) {
      const Vec3 x = composite.curves[s.curve].point(j / 16.0);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  }
  const double size = (hi - lo).norm();
  const auto angle = [](const Vec3& a, const Vec3& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
  };
  for (std::size_t i = 0; i < patch.sides.size(); ++i) {
    const ConicArc& curve = composite.curves[patch.sides[i].curve];
    const Surface& ribbon = *ip->ribbons()[i];
    const Surface& bound = *ip->bounds()[i];
    for (int k = 1; k < 8; ++k) {
      const double t = k / 8.0, dt = 1e-4;
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
        constexpr int kSteps = 32;
        double best = HUGE_VAL;
        Vec3 root = q;
        double previous = ip->value(q - 2.0 * delta * nr);
        for (int j = 1; j <= kSteps; ++j) {
          const double s0 = -2.0 * delta + 4.0 * delta * (j - 1) / kSteps;
          const double s1 = -2.0 * delta + 4.0 * delta * j / kSteps;
          const double value = ip->value(q + s1 * nr);
          if ((value > 0.0) != (previous > 0.0)) {
            double a = s0, b = s1;
            const bool a_positive = previous > 0.0;
            for (int halving = 0; halving < 40; ++halving) {
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
                             : 180.0;
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
    for (int k = 1; k < 16; ++k) {
      const Vec3 x = curve.point(k / 16.0);
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        const ValueGradient b = patch.bounds[j]->value_gradient(x);
        const double outside = -b.value / std::max(b.gradient.norm(), 1e-300);
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
    if (exit.distance > 1e-9 * shape.size) {
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
