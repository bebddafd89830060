#include "self_intersection.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>
#include <utility>
#include <vector>

namespace isopatch::test {

std::size_t count_self_intersections(const Mesh& mesh, std::size_t limit) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using Face = SurfaceMesh::Face_index;
  // A triangle soup is enough for the check; build it without requiring manifoldness.
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(mesh.positions.size());
  for (const Vec3& p : mesh.positions) v.push_back(sm.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  for (const Triangle& t : mesh.triangles) {
    if (sm.add_face(v[t[0]], v[t[1]], v[t[2]]) == SurfaceMesh::null_face()) {
      // Non-manifold input cannot be represented; callers check topology first.
      return limit;
    }
  }
  std::vector<std::pair<Face, Face>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(sm, std::back_inserter(pairs));
  return std::min(pairs.size(), limit);
}

}  // namespace isopatch::test
