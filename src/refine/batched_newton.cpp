// Batched Newton projection onto f = 0, free or within a cut plane (batched_newton.hpp).
#include "refine/batched_newton.hpp"

#include <cmath>
#include <vector>

namespace isopatch::refine {

void land_on_surface(const Sampler& f, const BoundaryPlanes& planes, std::span<NewtonPoint> points,
                     const NewtonLimits& limits) {
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
  // max_steps steps, and one more evaluation that confirms the last of them.
  for (int round = 0; round <= limits.max_steps && !active.empty(); ++round) {
    at.resize(active.size());
    vg.resize(active.size());
    for (std::size_t a = 0; a < active.size(); ++a) at[a] = points[active[a]].position;
    f.value_gradients(at, vg);
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
