// Discrete mean and Gaussian curvature (Meyer, Desbrun, Schroeder, Barr 2003). Every triangle adds its
// share to three per-vertex accumulators: the cotangent-weighted edge vectors (the mean-curvature
// normal, up to the area), the mixed Voronoi area and the corner angle. The mixed area uses the
// Voronoi region inside non-obtuse triangles and falls back to half or a quarter of the triangle when
// it is obtuse, so the areas still tile the surface and sum to its total area.
#include <isopatch/curvature.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <numbers>

#include "mesh_neighbourhood.hpp"

namespace isopatch {

DiscreteCurvature discrete_curvature(const Mesh& mesh) {
  analysis::check_mesh(mesh, "discrete_curvature");
  const std::size_t n = mesh.positions.size();
  const analysis::MeshNeighbourhood hood = analysis::mesh_neighbourhood(mesh);
  const std::vector<Vec3> normals = analysis::area_weighted_normals(mesh);

  std::vector<Vec3> laplace(n, Vec3::Zero());  // sum of (cot a + cot b) (x_i - x_j)
  std::vector<double> area(n, 0.0);
  std::vector<double> angle_sum(n, 0.0);
  std::vector<bool> touches_degenerate(n, false);

  for (const Triangle& t : mesh.triangles) {
    if (analysis::repeats_vertex(t)) continue;
    const Vec3* x[3] = {&mesh.positions[t[0]], &mesh.positions[t[1]], &mesh.positions[t[2]]};
    const double twice_area = (*x[1] - *x[0]).cross(*x[2] - *x[0]).norm();
    if (!(twice_area > 0.0)) {
      for (std::uint32_t v : t) touches_degenerate[v] = true;
      continue;
    }
    double cot[3];
    double angle[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = *x[(k + 1) % 3] - *x[k];
      const Vec3 w = *x[(k + 2) % 3] - *x[k];
      cot[k] = u.dot(w) / twice_area;  // |u x w| is twice the area at every corner
      angle[k] = analysis::angle_between(u, w);
    }
    const int obtuse = angle[0] > std::numbers::pi / 2   ? 0
                       : angle[1] > std::numbers::pi / 2 ? 1
                       : angle[2] > std::numbers::pi / 2 ? 2
                                                         : -1;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = t[static_cast<std::size_t>(k)];
      const int i = (k + 1) % 3;
      const int j = (k + 2) % 3;
      const Vec3 to_i = *x[k] - *x[i];
      const Vec3 to_j = *x[k] - *x[j];
      // Edge (k, i) is opposite corner j, edge (k, j) opposite corner i.
      laplace[v] += cot[j] * to_i + cot[i] * to_j;
      angle_sum[v] += angle[k];
      if (obtuse < 0)
        area[v] += (to_i.squaredNorm() * cot[j] + to_j.squaredNorm() * cot[i]) / 8.0;
      else
        area[v] += twice_area / (obtuse == k ? 4.0 : 8.0);
    }
  }

  const double nan = std::numeric_limits<double>::quiet_NaN();
  DiscreteCurvature result;
  result.mean.assign(n, nan);
  result.gaussian.assign(n, nan);
  result.area = area;
  result.interior = hood.interior;
  for (std::size_t v = 0; v < n; ++v) {
    if (!hood.interior[v] || touches_degenerate[v] || !(area[v] > 0.0)) continue;
    const double length = normals[v].norm();
    if (!(length > 0.0)) continue;
    // K(x) = laplace / (2 A); H = K(x) . n / 2.
    result.mean[v] = laplace[v].dot(normals[v] / length) / (4.0 * area[v]);
    result.gaussian[v] = (2.0 * std::numbers::pi - angle_sum[v]) / area[v];
  }
  return result;
}

}  // namespace isopatch
