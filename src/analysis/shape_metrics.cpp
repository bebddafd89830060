// Element shape and valence metrics (docs/algorithms.md 7.1).
#include <isopatch/metrics.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh_neighbourhood.hpp"

namespace isopatch {
namespace {

struct TriangleShape {
  double min_angle = 0.0;  // degrees
  double aspect_ratio = std::numeric_limits<double>::infinity();
  double quality = 0.0;
};

TriangleShape triangle_shape(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const double a = (p2 - p1).norm();  // opposite p0
  const double b = (p0 - p2).norm();  // opposite p1
  const double c = (p1 - p0).norm();  // opposite p2
  const double area = 0.5 * (p1 - p0).cross(p2 - p0).norm();
  TriangleShape s;
  // A zero-area triangle keeps the limits: angle 0, aspect ratio +inf, quality 0.
  if (!(area > 0.0)) return s;
  s.min_angle = analysis::smallest_angle_degrees(p0, p1, p2);
  const double semiperimeter = 0.5 * (a + b + c);
  // R / (2 r) with R = abc / (4 A) and r = A / p.
  s.aspect_ratio = a * b * c * semiperimeter / (8.0 * area * area);
  s.quality = 6.0 / std::sqrt(3.0) * area / (semiperimeter * std::max({a, b, c}));
  return s;
}

double share_below(const std::vector<double>& values, double limit) {
  if (values.empty()) return 0.0;
  const auto n = std::count_if(values.begin(), values.end(), [&](double v) { return v < limit; });
  return static_cast<double>(n) / static_cast<double>(values.size());
}

}  // namespace

ShapeReport analyze_shape(const Mesh& mesh) {
  analysis::check_mesh(mesh, "analyze_shape");
  const std::size_t f = mesh.triangles.size();
  std::vector<double> angles(f), aspects(f), qualities(f);
  for (std::size_t t = 0; t < f; ++t) {
    const Triangle& tri = mesh.triangles[t];
    const TriangleShape s =
        triangle_shape(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]);
    angles[t] = s.min_angle;
    aspects[t] = s.aspect_ratio;
    qualities[t] = s.quality;
  }
  ShapeReport report;
  report.share_below_10 = share_below(angles, 10.0);
  report.share_below_20 = share_below(angles, 20.0);
  report.share_below_30 = share_below(angles, 30.0);
  report.min_angle = summarize(std::move(angles));
  report.aspect_ratio = summarize(std::move(aspects));
  report.quality = summarize(std::move(qualities));

  const analysis::MeshNeighbourhood hood = analysis::mesh_neighbourhood(mesh);
  std::vector<double> lengths;
  lengths.reserve(hood.edges.size());
  for (const analysis::Edge& e : hood.edges)
    lengths.push_back((mesh.positions[e.a] - mesh.positions[e.b]).norm());
  double mean = 0.0;
  for (double l : lengths) mean += l;
  mean /= std::max<double>(1.0, static_cast<double>(lengths.size()));
  double variance = 0.0;
  for (double l : lengths) variance += (l - mean) * (l - mean);
  variance /= std::max<double>(1.0, static_cast<double>(lengths.size()));
  report.edge_length_cv = mean > 0.0 ? std::sqrt(variance) / mean : 0.0;
  report.edge_length = summarize(std::move(lengths));
  return report;
}

SmallAngleCount count_small_angles(const Mesh& mesh, double degrees) {
  analysis::check_mesh(mesh, "count_small_angles");
  SmallAngleCount count;
  for (const Triangle& tri : mesh.triangles) {
    const double angle = analysis::smallest_angle_degrees(mesh.positions[tri[0]], mesh.positions[tri[1]],
                                                          mesh.positions[tri[2]]);
    if (angle < degrees) ++count.triangles;
    count.smallest = std::min(count.smallest, angle);
  }
  return count;
}

ValenceReport analyze_valence(const Mesh& mesh) {
  analysis::check_mesh(mesh, "analyze_valence");
  const analysis::MeshNeighbourhood hood = analysis::mesh_neighbourhood(mesh);
  ValenceReport report;
  std::size_t regular = 0;
  std::size_t near_regular = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (!hood.referenced[v]) continue;
    if (!hood.interior[v]) {
      ++report.other_vertices;
      continue;
    }
    const std::uint32_t k = hood.valence[v];
    if (report.histogram.size() <= k) report.histogram.resize(k + 1, 0);
    ++report.histogram[k];
    ++report.interior_vertices;
    if (k == 6) ++regular;
    if (k >= 5 && k <= 7) ++near_regular;
  }
  if (report.interior_vertices > 0) {
    const auto n = static_cast<double>(report.interior_vertices);
    report.share_6 = static_cast<double>(regular) / n;
    report.share_5_to_7 = static_cast<double>(near_regular) / n;
  }
  return report;
}

}  // namespace isopatch
