#pragma once
/// \file peer_mesher.hpp
/// The CGAL peer of the quality report: CGAL's Surface_mesher (Delaunay refinement, Boissonnat & Oudot)
/// run on an isopatch Surface, so that both systems mesh exactly the same f. Benchmark code only: the
/// isopatch library never depends on CGAL.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>

namespace isopatch::bench {

/// Parameters of CGAL::Surface_mesh_default_criteria_3 and of the implicit-surface oracle.
struct PeerOptions {
  double angle_bound = 30.0;   ///< degrees: smallest angle of a surface Delaunay facet
  double radius_bound = 0.05;  ///< largest radius of a facet's surface Delaunay ball (the size knob)
  double distance_bound = 0;   ///< largest centre-to-circumcentre distance; <= 0 means radius_bound / 10
  /// Bisection precision of the oracle, relative to the bounding-sphere radius. CGAL's default is
  /// 1e-3, which leaves vertices so far from f = 0 that curvature estimates measure the bisection, not
  /// the mesh; 1e-9 puts them on the surface to about the precision isopatch reaches.
  double error_bound = 1e-9;
  int initial_points = 20;      ///< points on the surface found by random rays before refinement
  bool keep_box_faces = false;  ///< keep the facets that close an open surface along the box walls
};

/// What the peer produced, with what it needed.
struct PeerResult {
  Mesh mesh;                           ///< triangles counter-clockwise seen from outside (along grad f)
  double seconds = 0.0;                ///< wall time: seed search, refinement, extraction (not the clean-up)
  Vec3 seed = Vec3::Zero();            ///< centre of the bounding sphere (a point with f < 0)
  double sphere_radius = 0.0;          ///< radius of the bounding sphere (it contains the whole box)
  std::size_t box_facets_removed = 0;  ///< facets dropped because they lie on a box wall
  std::size_t non_finite_values = 0;   ///< evaluations of f that were NaN or infinite (counted positive)
};

/// Meshes f = 0 inside `box` with CGAL::make_surface_mesh (Manifold_tag) and the default criteria.
/// The oracle sees f clipped to the box: inside the box the sign of f, with f = 0 counted positive
/// (isopatch's sign rule); outside the box always positive. A closed surface strictly inside its box
/// is therefore meshed unchanged; an open surface (gyroid) is closed by the box walls, and those wall
/// facets (a corner inside a wall, off f = 0, or all corners on walls) are removed afterwards unless
/// options.keep_box_faces. The bounding sphere is centred at the
/// sample of the box with the most negative f / |grad f| (the deepest interior point found on a grid),
/// so the oracle's initial rays start inside the solid.
/// Limitation: refinement only grows from the initial points, so a surface with several components
/// can lose the components that no initial ray reaches (none of the public surfaces has several).
/// \throw NoSurfaceError when no sample of the box has f < 0 (nothing to mesh)
/// \throw InputError for an invalid box or non-positive bounds
PeerResult cgal_surface_mesh(const Surface& surface, const Box& box, const PeerOptions& options);

}  // namespace isopatch::bench
