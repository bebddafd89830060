// Element shape and valence away from given points (metrics.hpp, analyze_shape_away).
#include <isopatch/error.hpp>
#include <isopatch/metrics.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/point_grid.hpp"
#include "mesh_neighbourhood.hpp"

namespace isopatch {
namespace {

/// Whether a point lies in a closed ball of radius r about one of the centres (PointGrid of side r).
class BallSet {
 public:
  BallSet(std::span<const Vec3> centres, double radius) : centres_(centres), radius_(radius), grid_(radius) {
    for (std::size_t i = 0; i < centres.size(); ++i) grid_.insert(centres[i], i);
  }
  bool contains(const Vec3& p) const {
    bool inside = false;
    grid_.near(p, [&](std::size_t i) { inside = inside || (centres_[i] - p).norm() <= radius_; });
    return inside;
  }

 private:
  std::span<const Vec3> centres_;
  double radius_;
  PointGrid grid_;
};

}  // namespace

ShapeAwayReport analyze_shape_away(const Mesh& mesh, std::span<const Vec3> centres, double radius) {
  analysis::check_mesh(mesh, "analyze_shape_away");
  if (!(std::isfinite(radius) && radius > 0.0))
    throw InputError("analyze_shape_away: the radius must be a positive number");
  for (const Vec3& c : centres)
    if (!c.allFinite()) throw InputError("analyze_shape_away: a centre is not finite");
  ShapeAwayReport report;
  report.radius = radius;
  report.centres = centres.size();
  const BallSet balls(centres, radius);
  std::vector<bool> near(mesh.positions.size(), false);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) near[v] = balls.contains(mesh.positions[v]);
  std::size_t below_20 = 0;
  for (const Triangle& t : mesh.triangles) {
    if (near[t[0]] || near[t[1]] || near[t[2]]) {
      ++report.triangles_near;
      continue;
    }
    ++report.triangles;
    const double angle =
        analysis::smallest_angle_degrees(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    report.smallest_angle = std::min(report.smallest_angle, angle);
    if (angle < 20.0) ++below_20;
  }
  if (report.triangles > 0)
    report.share_below_20 = static_cast<double>(below_20) / static_cast<double>(report.triangles);
  const analysis::MeshNeighbourhood hood = analysis::mesh_neighbourhood(mesh);
  std::size_t regular = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (!hood.referenced[v] || !hood.interior[v] || near[v]) continue;
    ++report.interior_vertices;
    if (hood.valence[v] == 6) ++regular;
  }
  if (report.interior_vertices > 0)
    report.share_6 = static_cast<double>(regular) / static_cast<double>(report.interior_vertices);
  return report;
}

}  // namespace isopatch
