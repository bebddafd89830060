#include "orient.hpp"

#include <cmath>
#include <utility>

namespace isopatch::bench {

void orient_along_gradient(Mesh& mesh, const Surface& surface) {
  double vote = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.positions[t[0]];
    const Vec3& b = mesh.positions[t[1]];
    const Vec3& c = mesh.positions[t[2]];
    const Vec3 g = surface.value_gradient((a + b + c) / 3.0).gradient;
    const double d = (b - a).cross(c - a).dot(g);
    if (std::isfinite(d)) vote += d;
  }
  if (vote < 0.0)
    for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace isopatch::bench
