#include "isotropic_remesh.hpp"

#include <isopatch/error.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <chrono>
#include <cmath>
#include <vector>

#include "to_mesh.hpp"

namespace isopatch::bench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

double area(const Mesh& mesh) {
  double sum = 0.0;
  for (const Triangle& t : mesh.triangles)
    sum += 0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]])
                     .cross(mesh.positions[t[2]] - mesh.positions[t[0]])
                     .norm();
  return sum;
}

double mean_edge(const Mesh& mesh) {
  double sum = 0.0;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      sum += (mesh.positions[t[static_cast<std::size_t>(i)]] -
              mesh.positions[t[static_cast<std::size_t>((i + 1) % 3)]])
                 .norm();
  return sum / (3.0 * static_cast<double>(mesh.triangles.size()));  // interior edges counted twice, alike
}

}  // namespace

RemeshResult isotropic_remesh(const Mesh& input, const RemeshOptions& options) {
  if (input.triangles.empty()) throw InputError("the mesh to remesh has no triangles");
  if (options.iterations < 1) throw InputError("remeshing needs at least one iteration");
  RemeshResult r;
  if (options.target_edge > 0.0)
    r.target_edge = options.target_edge;
  else if (options.target_vertices > 0.0)
    r.target_edge = std::sqrt(2.0 * area(input) / (std::sqrt(3.0) * options.target_vertices));
  else
    r.target_edge = mean_edge(input);
  if (!(r.target_edge > 0.0) || !std::isfinite(r.target_edge))
    throw InputError("no positive target edge length");

  const auto start = std::chrono::steady_clock::now();
  std::vector<Point_3> points;
  points.reserve(input.positions.size());
  for (const Vec3& p : input.positions) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::array<std::size_t, 3>> soup;
  soup.reserve(input.triangles.size());
  for (const Triangle& t : input.triangles) soup.push_back({t[0], t[1], t[2]});
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup))
    throw InputError("the mesh to remesh is not a manifold polygon mesh");
  CgalMesh cgal;
  PMP::polygon_soup_to_polygon_mesh(points, soup, cgal);
  PMP::isotropic_remeshing(faces(cgal), r.target_edge, cgal,
                           CGAL::parameters::number_of_iterations(options.iterations));
  cgal.collect_garbage();
  r.mesh = to_mesh(cgal);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace isopatch::bench
