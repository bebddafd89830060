// Batched Newton projection onto f = 0, free or within a cut plane (batched_newton.hpp).
#include "refine/batched_newton.hpp"

#include <cmath>
#include <vector>

namespace isopatch::refine {
void value_gradients(std::span<const Sampler* const> functions, std::span<const Vec3> at,
                     std::span<const std::uint32_t> piece, std::span<ValueGradient> out) {
  if (functions.size() == 1 || piece.empty()) {
    functions[0]->value_gradients(at, out);
    return;
  }
  // The points grouped by piece (a counting sort keeps their order within a piece).
  std::vector<std::size_t> first(functions.size() + 1, 0);
  for (const std::uint32_t f : piece) ++first[f + 1];
  for (std::size_t f = 0; f < functions.size(); ++f) first[f + 1] += first[f];
  std::vector<std::size_t> order(at.size());
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for (std::size_t i = 0; i < at.size(); ++i) order[next[piece[i]]++] = i;
  }
  std::vector<Vec3> group_at;
  std::vector<ValueGradient> group_out;
  for (std::size_t f = 0; f < functions.size(); ++f) {
    const std::size_t n = first[f + 1] - first[f];
    if (n == 0) continue;
    group_at.resize(n);
    group_out.resize(n);
    for (std::size_t g = 0; g < n; ++g) group_at[g] = at[order[first[f] + g]];
    functions[f]->value_gradients(group_at, group_out);
    for (std::size_t g = 0; g < n; ++g) out[order[first[f] + g]] = group_out[g];
  }
}

void land_on_surface(const Sampler& f, const BoundaryPlanes& planes, std::span<NewtonPoint> points,
                     const NewtonLimits& limits) {
  const Sampler* const one[] = {&f};
  for (NewtonPoint& p : points) p.piece = 0;
  land_on_surface(one, planes, points, limits);
}

void land_on_surface(std::span<const Sampler* const> functions, const BoundaryPlanes& planes,
                     std::span<NewtonPoint> points, const NewtonLimits& limits) {
  std::vector<std::uint32_t> active;
  active.reserve(points.size());
  std::vector<Vec3> start(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    NewtonPoint& p = points[i];
    if (p.plane >= 0) p.position = planes.onto(static_cast<std::size_t>(p.plane), p.position);
    start[i] = p.position;
    p.landing = Landing::Stalled;
    active.push_back(static_cast<std::uint32_t>(i));
  }
  std::vector<Vec3> at;
  std::vector<ValueGradient> vg;
  std::vector<std::uint32_t> piece;
  // max_steps steps, and one more evaluation that confirms the last of them.
  for (int round = 0; round <= limits.max_steps && !active.empty(); ++round) {
    at.resize(active.size());
    vg.resize(active.size());
    piece.resize(functions.size() > 1 ? active.size() : 0);
    for (std::size_t a = 0; a < active.size(); ++a) at[a] = points[active[a]].position;
    for (std::size_t a = 0; a < piece.size(); ++a) piece[a] = points[active[a]].piece;
    value_gradients(functions, at, piece, vg);
    std::size_t kept = 0;
    for (std::size_t a = 0; a < active.size(); ++a) {
      NewtonPoint& p = points[active[a]];
      Vec3 g = vg[a].gradient;
      const double gradient_length = g.norm();
      if (p.plane >= 0) {
        const Vec3& m = planes[static_cast<std::size_t>(p.plane)].normal;
        g -= g.dot(m) * m;
      }
      const double g2 = g.squaredNorm();
      if (!(g2 > 0.0) || !(gradient_length > 0.0)) continue;  // Stalled
      const double distance = std::abs(vg[a].value) / std::sqrt(g2);
      if (distance <= limits.tolerance) {
        p.normal = vg[a].gradient / gradient_length;
        if ((p.position - start[active[a]]).norm() > p.max_move)
          p.landing = Landing::TooFar;
        else if (p.expected_normal.squaredNorm() > 0.0 &&
                 p.normal.dot(p.expected_normal) <= limits.min_normal_dot)
          p.landing = Landing::TurnedAway;
        else
          p.landing = Landing::Ok;
        continue;
      }
      if (round == limits.max_steps) continue;  // Stalled
      Vec3 step = (vg[a].value / g2) * g;
      const double length = step.norm();
      if (length > p.max_move) step *= p.max_move / length;  // one step may not leave the allowed ball
      p.position -= step;
      if (p.plane >= 0) p.position = planes.onto(static_cast<std::size_t>(p.plane), p.position);
      if ((p.position - start[active[a]]).norm() > 2.0 * p.max_move) {
        p.landing = Landing::TooFar;
        continue;
      }
      active[kept++] = active[a];
    }
    active.resize(kept);
  }
}

}  // namespace isopatch::refine
