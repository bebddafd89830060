#include "peer_mesher.hpp"

#include <isopatch/error.hpp>

#include <CGAL/Complex_2_in_triangulation_3.h>
#include <CGAL/IO/facets_in_complex_2_to_triangle_mesh.h>
#include <CGAL/Implicit_surface_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_default_criteria_3.h>
#include <CGAL/Surface_mesh_default_triangulation_3.h>
#include <CGAL/make_surface_mesh.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "interior_seed.hpp"
#include "peer_support/orient.hpp"
#include "to_mesh.hpp"

namespace isopatch::bench {
namespace {

using Tr = CGAL::Surface_mesh_default_triangulation_3;
using C2t3 = CGAL::Complex_2_in_triangulation_3<Tr>;
using GT = Tr::Geom_traits;
using Point_3 = GT::Point_3;
using Sphere_3 = GT::Sphere_3;
using FT = GT::FT;
using Implicit = CGAL::Implicit_surface_3<GT>;
using CgalMesh = CGAL::Surface_mesh<Point_3>;

// True when p lies within `tol` of a wall of the box.
bool on_box_boundary(const Vec3& p, const Box& box, double tol) {
  return ((p - box.lo).array().abs() <= tol).any() || ((p - box.hi).array().abs() <= tol).any();
}

// True when p is farther than `tol` from f = 0 (first-order estimate |f| / |grad f|).
bool off_surface(const Surface& surface, const Vec3& p, double tol) {
  const ValueGradient vg = surface.value_gradient(p);
  const double g = vg.gradient.norm();
  return !(std::abs(vg.value) <= tol * g);
}

// Drops the facets closing the surface along the box walls, and the vertices no longer used: a facet
// with a corner off f = 0 (inside a wall), or with all three corners on walls (along the rim).
// Returns the number of facets dropped.
std::size_t remove_box_facets(Mesh& mesh, const Surface& surface, const Box& box, double wall_tol,
                              double surface_tol) {
  std::vector<char> off(mesh.positions.size()), wall(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    wall[v] = on_box_boundary(mesh.positions[v], box, wall_tol);
    off[v] = wall[v] && off_surface(surface, mesh.positions[v], surface_tol);
  }
  std::vector<Triangle> kept;
  kept.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    if (!(off[t[0]] || off[t[1]] || off[t[2]]) && !(wall[t[0]] && wall[t[1]] && wall[t[2]]))
      kept.push_back(t);
  const std::size_t removed = mesh.triangles.size() - kept.size();
  if (removed == 0) return 0;
  constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> remap(mesh.positions.size(), kUnused);
  std::vector<Vec3> positions;
  for (Triangle& t : kept)
    for (std::uint32_t& v : t) {
      if (remap[v] == kUnused) {
        remap[v] = static_cast<std::uint32_t>(positions.size());
        positions.push_back(mesh.positions[v]);
      }
      v = remap[v];
    }
  mesh.positions = std::move(positions);
  mesh.triangles = std::move(kept);
  return removed;
}

}  // namespace

PeerResult cgal_surface_mesh(const Surface& surface, const Box& box, const PeerOptions& options) {
  if (!box.valid()) throw InputError("invalid box");
  if (!(options.radius_bound > 0.0) || !(options.angle_bound > 0.0) || !(options.error_bound > 0.0) ||
      options.initial_points < 1)
    throw InputError("the CGAL criteria need positive bounds and at least one initial point");
  const double distance_bound =
      options.distance_bound > 0.0 ? options.distance_bound : options.radius_bound / 10.0;

  PeerResult result;
  const auto start = std::chrono::steady_clock::now();
  const std::optional<Vec3> seed = deepest_interior_sample(surface, box);
  if (!seed) throw NoSurfaceError("no sample of the box has f < 0: nothing for the CGAL peer to mesh");
  result.seed = *seed;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c((corner & 1) ? box.hi.x() : box.lo.x(), (corner & 2) ? box.hi.y() : box.lo.y(),
                 (corner & 4) ? box.hi.z() : box.lo.z());
    result.sphere_radius = std::max(result.sphere_radius, (c - *seed).norm());
  }
  result.sphere_radius *= 1.01;  // the sphere strictly contains the box, so f is positive on it

  std::size_t non_finite = 0;
  auto clipped = [&surface, &box, &non_finite](const Point_3& p) -> FT {
    const Vec3 q(p.x(), p.y(), p.z());
    if (!box.contains(q)) return 1.0;
    const double f = surface.value(q);
    if (!std::isfinite(f)) {
      ++non_finite;
      return 1.0;
    }
    return f < 0.0 ? f : std::max(f, std::numeric_limits<double>::min());  // f = 0 counts positive
  };
  Tr triangulation;
  C2t3 complex(triangulation);
  const Implicit implicit(
      clipped,
      Sphere_3(Point_3(seed->x(), seed->y(), seed->z()), result.sphere_radius * result.sphere_radius),
      options.error_bound);
  const CGAL::Surface_mesh_default_criteria_3<Tr> criteria(options.angle_bound, options.radius_bound,
                                                           distance_bound);
  CGAL::make_surface_mesh(complex, implicit, criteria, CGAL::Manifold_tag(), options.initial_points);

  CgalMesh cgal;
  CGAL::facets_in_complex_2_to_triangle_mesh(complex, cgal);
  result.mesh = to_mesh(cgal);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!options.keep_box_faces) {
    // Oracle points are within error_bound * radius of where the sign changes; a wall point of the
    // surface itself is as close to f = 0, a point inside a wall is far from it.
    const double tol = 4.0 * options.error_bound * result.sphere_radius + 1e-12 * box.diagonal();
    result.box_facets_removed = remove_box_facets(result.mesh, surface, box, tol, 1e-6 * box.diagonal());
  }
  orient_along_gradient(result.mesh, surface);
  result.non_finite_values = non_finite;
  return result;
}

}  // namespace isopatch::bench
