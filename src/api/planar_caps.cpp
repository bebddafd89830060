// Planar caps closing a smooth surface cut open by a convex polyhedron (planar_caps.hpp).
#include "api/planar_caps.hpp"

#include <isopatch/error.hpp>
#include <isopatch/remesh.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "api/cap_wedges.hpp"
#include "api/exact_positions.hpp"
#include "api/facet_polygons.hpp"
#include "csg/face_set.hpp"
#include "planar/graded_division.hpp"
#include "planar/lattice_points.hpp"
#include "planar/region_triangulation.hpp"
#include "remesh/remesh_presets.hpp"

namespace isopatch {

namespace {

using Edge = std::array<std::uint32_t, 2>;

/// A cap's lattice points keep this share of an edge from its boundary (the clean-up evens the band).
constexpr double kLatticeClearance = 0.5;
/// A corner of the cut or a cap narrower than this (degrees) keeps one triangle per 60 degrees of it:
/// more would split its angle under the 25 degree floor (cap_wedges.hpp).
constexpr double kNarrowCorner = 150.0;
/// A vertex moved there is put back on its surface to this share of the on-plane tolerance.
constexpr double kSettle = 1e-5;

std::string where(const Vec3& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()) + ")";
}

/// The mesh's boundary edges, directed as their one triangle runs them, in triangle order: the directed
/// edges (a, b) without a directed edge (b, a), found in b's outgoing edges (each vertex's targets in
/// one array: two passes over the triangles, no hashing, for the millions of a large part).
std::vector<Edge> boundary_edges(const Mesh& mesh) {
  std::vector<std::uint64_t> first(mesh.positions.size() + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (const std::uint32_t v : t) ++first[v + 1];
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) first[v + 1] += first[v];
  std::vector<std::uint32_t> targets(first.back());
  std::vector<std::uint64_t> filled(first.begin(), first.end() - 1);
  for (const Triangle& t : mesh.triangles)
    for (std::size_t k = 0; k < 3; ++k) targets[filled[t[k]]++] = t[(k + 1) % 3];
  const auto has_edge = [&](std::uint32_t a, std::uint32_t b) {
    return std::find(targets.begin() + static_cast<std::ptrdiff_t>(first[a]),
                     targets.begin() + static_cast<std::ptrdiff_t>(first[a + 1]),
                     b) != targets.begin() + static_cast<std::ptrdiff_t>(first[a + 1]);
  };
  std::vector<Edge> out;
  for (const Triangle& t : mesh.triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (!has_edge(b, a)) out.push_back({a, b});
    }
  return out;
}

/// The pieces of the polyhedron's edges inside the solid, sampled once: chains of vertex ids from the
/// side's first corner towards its second, shared by the two faces beside it.
struct EdgeChains {
  Vec3 from, to;
  std::vector<std::vector<std::uint32_t>> chains;
};

class CapBuilder {
 public:
  CapBuilder(Mesh& mesh, const Surface* smooth, const ConvexRegion& planes, std::size_t capped,
             const Box& box, double edge, double tolerance, const Settings& settings, bool narrow_corners)
      : narrow_corners_(narrow_corners),
        mesh_(mesh),
        smooth_(smooth),
        planes_(planes),
        capped_(capped),
        box_(box),
        edge_(edge),
        tol_(tolerance),
        settings_(settings),
        boundary_(boundary_edges(mesh)),
        assigned_(boundary_.size(), 0) {
    for (std::size_t e = 0; e < boundary_.size(); ++e)
      for (std::uint32_t v : boundary_[e]) {
        if (seen_.insert(v).second) cut_vertices_.push_back(v);
        boundary_at_[v].push_back(e);
      }
    // Sizes that vary (an error bound, a size field) make the cut's edges shorter than the largest size
    // where it meets the planes: the caps follow the cut's mean edge there, not the largest size.
    if ((settings.max_error || settings.size_field) && !boundary_.empty()) {
      double sum = 0.0;
      for (const Edge& e : boundary_) sum += (mesh_.positions[e[0]] - mesh_.positions[e[1]]).norm();
      edge_ = std::min(edge_, sum / static_cast<double>(boundary_.size()));
    }
  }

  CapReport run() {
    // The cut's own narrow corners, where it meets a polyhedron edge or corner (cap_wedges.hpp).
    if (smooth_ && narrow_corners_) {
      std::vector<bool> held(mesh_.positions.size(), false);
      for (std::uint32_t v : cut_vertices_) held[v] = true;
      open_narrow_corners(mesh_, *smooth_, held, kNarrowCorner, kSettle * tol_);
    }
    const std::vector<FacetPolygon> facets = facet_polygons(planes_, box_);
    CapReport report;
    report.crease_vertices = cut_vertices_.size();
    const std::size_t before = mesh_.positions.size();
    // The caps' boundaries first (they share the polyhedron's edges), then each cap on its own, side by
    // side (the same caps for any thread count), added to the mesh in plane order.
    std::vector<std::vector<Edge>> segments(capped_);
    for (std::size_t i = 0; i < capped_; ++i)
      if (!facets[i].corners.empty()) segments[i] = cap_segments(static_cast<int>(i), facets[i]);
    std::vector<Mesh> caps(capped_);
    tbb::parallel_for(std::size_t{0}, capped_, [&](std::size_t i) {
      if (!segments[i].empty()) caps[i] = cap(static_cast<int>(i), facets[i], segments[i]);
    });
    for (std::size_t i = 0; i < capped_; ++i)
      if (!segments[i].empty()) {
        add_cap(caps[i], segments[i]);
        ++report.caps;
      }
    for (std::size_t e = 0; e < boundary_.size(); ++e)
      if (assigned_[e] == 0 &&
          on_open_face(mesh_.positions[boundary_[e][0]], mesh_.positions[boundary_[e][1]]))
        ++report.open_edges;  // the box or a region plane cuts the part open there
      else if (assigned_[e] != 1)
        throw CreaseError("the cut of the smooth part has an edge on " + std::to_string(assigned_[e]) +
                          " of the capping planes near " + where(mesh_.positions[boundary_[e][0]]) +
                          " (a plane tangent to the surface there?); --creases off meshes it as a smooth "
                          "surface");
    drop_unused_vertices(before);
    // The caps' vertices in the attributes of the cut (--vertex-roles: made by the caps' clean-up).
    for (VertexAttribute& a : mesh_.attributes)
      a.values.resize(mesh_.positions.size(), a.name == "role" ? 5.0f : 0.0f);
    report.cap_vertices = mesh_.positions.size() - before;
    report.crease_vertices += edge_vertices_;
    report.open_cap_edges = open_cap_edges_;
    return report;
  }

 private:
  bool narrow_corners_;
  Mesh& mesh_;
  const Surface* smooth_;
  const ConvexRegion& planes_;
  std::size_t capped_;
  const Box& box_;
  double edge_, tol_;
  const Settings& settings_;
  std::vector<Edge> boundary_;
  std::vector<int> assigned_;
  std::unordered_set<std::uint32_t> seen_;
  std::unordered_map<std::uint32_t, std::vector<std::size_t>>
      boundary_at_;  ///< the cut's boundary edges at v
  std::vector<std::uint32_t> cut_vertices_;
  std::vector<std::pair<Vec3, std::uint32_t>> corners_;
  std::map<std::pair<int, int>, EdgeChains> chains_;
  std::size_t edge_vertices_ = 0;
  std::size_t open_cap_edges_ = 0;

  /// Removes the vertices from `first` on that no triangle uses (a corner of the polyhedron outside the
  /// solid), renumbering the rest in order.
  void drop_unused_vertices(std::size_t first) {
    std::vector<bool> used(mesh_.positions.size(), false);
    for (const Triangle& t : mesh_.triangles)
      for (std::uint32_t v : t) used[v] = true;
    std::vector<std::uint32_t> id(mesh_.positions.size());
    std::size_t kept = first;
    for (std::size_t v = 0; v < mesh_.positions.size(); ++v) {
      if (v >= first && !used[v]) continue;
      id[v] = static_cast<std::uint32_t>(v < first ? v : kept);
      if (v >= first) mesh_.positions[kept++] = mesh_.positions[v];
    }
    mesh_.positions.resize(kept);
    for (Triangle& t : mesh_.triangles)
      for (std::uint32_t& v : t) v = id[v];
  }

  std::uint32_t add_vertex(const Vec3& p) {
    mesh_.positions.push_back(p);
    return static_cast<std::uint32_t>(mesh_.positions.size() - 1);
  }

  /// One vertex per corner of the polyhedron, however many faces compute it: the cut's own vertex where
  /// g = 0 passes through the corner (a gyroid through the corners of a box of whole periods).
  std::uint32_t corner(const Vec3& p) {
    for (const auto& [q, id] : corners_)
      if ((q - p).norm() <= tol_) return id;
    for (std::uint32_t v : cut_vertices_)
      if ((mesh_.positions[v] - p).norm() <= tol_) {
        corners_.emplace_back(p, v);
        return v;
      }
    corners_.emplace_back(p, add_vertex(p));
    ++edge_vertices_;
    return corners_.back().second;
  }

  /// The faces of the box p lies on, one bit each (axis * 2, + 1 for the upper one).
  unsigned box_faces(const Vec3& p) const {
    unsigned faces = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (std::abs(p[axis] - box_.lo[axis]) <= tol_) faces |= 1u << (2 * axis);
      if (std::abs(p[axis] - box_.hi[axis]) <= tol_) faces |= 1u << (2 * axis + 1);
    }
    return faces;
  }

  /// Whether p and q lie on one face of the box or one region plane (planes from capped_ on).
  bool on_open_face(const Vec3& p, const Vec3& q) const {
    if (box_faces(p) & box_faces(q)) return true;
    for (std::size_t j = capped_; j < planes_.size(); ++j)
      if (on(static_cast<int>(j), p) && on(static_cast<int>(j), q)) return true;
    return false;
  }

  /// Whether p lies on plane `plane` (>= 0), or on box face -1 - plane (< 0).
  bool on(int plane, const Vec3& p) const {
    if (plane < 0) return (box_faces(p) >> (-1 - plane)) & 1u;
    return std::abs(plane_value(planes_[static_cast<std::size_t>(plane)], p)) <= tol_;
  }

  /// The size a side of planes i and j wants at its stop v: the mean length of the cut's boundary edges at
  /// v on either plane (where local sizes made the cut finer there), at most the caps' edge; 0 where v is
  /// no vertex of the cut (a corner of the polyhedron inside the solid).
  double size_at(std::uint32_t v, int i, int j) const {
    const auto it = boundary_at_.find(v);
    if (it == boundary_at_.end()) return 0.0;
    double sum = 0.0;
    int count = 0;
    for (std::size_t e : it->second) {
      const Vec3& p = mesh_.positions[boundary_[e][0]];
      const Vec3& q = mesh_.positions[boundary_[e][1]];
      if (!((on(i, p) && on(i, q)) || (on(j, p) && on(j, q)))) continue;
      sum += (p - q).norm();
      ++count;
    }
    return count == 0 ? 0.0 : std::min(edge_, sum / count);
  }

  /// The chains of the side from `a` to `b` on planes i and j (j < 0: box face -1 - j, a side only
  /// cap i has: the box cuts the part open along it), made on first use.
  const EdgeChains& side_chains(int i, int j, const Vec3& a, const Vec3& b) {
    const auto key = std::minmax(i, j);
    auto it = chains_.find(key);
    if (it != chains_.end()) return it->second;
    EdgeChains out{a, b, {}};
    const Vec3 d = b - a;
    // The cut's vertices on this edge of the polyhedron split it where g changes sign.
    std::vector<std::pair<double, std::uint32_t>> stops{{0.0, corner(a)}, {1.0, corner(b)}};
    for (std::uint32_t v : cut_vertices_) {
      const Vec3& p = mesh_.positions[v];
      if (!on(i, p) || !on(j, p)) continue;
      const double t = (p - a).dot(d) / d.squaredNorm();
      if (t > 0.0 && t < 1.0 && v != stops[0].second && v != stops[1].second) stops.emplace_back(t, v);
    }
    std::sort(stops.begin(), stops.end());
    for (std::size_t k = 0; k + 1 < stops.size(); ++k) {
      const Vec3 p = mesh_.positions[stops[k].second], q = mesh_.positions[stops[k + 1].second];
      if (smooth_ && !(smooth_->value(0.5 * (p + q)) < 0.0)) continue;
      std::vector<std::uint32_t> chain{stops[k].second};
      // As fine as the cut where it meets the side (a corner of the polyhedron takes the other end's size).
      double at_p = size_at(stops[k].second, i, j), at_q = size_at(stops[k + 1].second, i, j);
      if (at_p == 0.0) at_p = at_q == 0.0 ? edge_ : at_q;
      if (at_q == 0.0) at_q = at_p;
      for (const double t : planar::graded_division((q - p).norm(), at_p, at_q)) {
        chain.push_back(add_vertex(p + t * (q - p)));
        ++edge_vertices_;
      }
      chain.push_back(stops[k + 1].second);
      out.chains.push_back(std::move(chain));
    }
    return chains_.emplace(key, std::move(out)).first->second;
  }

  /// The directed segments bounding the cap of plane i (the cap on their left seen along its normal).
  std::vector<Edge> cap_segments(int i, const FacetPolygon& facet) {
    std::vector<Edge> out;
    const std::size_t n = facet.corners.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& a = facet.corners[k];
      const Vec3& b = facet.corners[(k + 1) % n];
      int across = facet.across[k];
      if (across < 0) {
        const unsigned face = box_faces(a) & box_faces(b);
        if (face == 0) throw CreaseError("a cap's side on the box lies on no face of it near " + where(a));
        across = -1 - std::countr_zero(face);
      }
      const EdgeChains& side = side_chains(i, across, a, b);
      const bool forward = (side.from - a).norm() <= (side.from - b).norm();
      for (const auto& chain : side.chains)
        for (std::size_t s = 0; s + 1 < chain.size(); ++s) {
          out.push_back(forward ? Edge{chain[s], chain[s + 1]} : Edge{chain[s + 1], chain[s]});
          if (across < 0 || across >= static_cast<int>(capped_)) ++open_cap_edges_;
        }
    }
    for (std::size_t e = 0; e < boundary_.size(); ++e) {
      const Vec3& p = mesh_.positions[boundary_[e][0]];
      const Vec3& q = mesh_.positions[boundary_[e][1]];
      if (!on(i, p) || !on(i, q)) continue;
      ++assigned_[e];
      out.push_back({boundary_[e][1], boundary_[e][0]});
    }
    return out;
  }

  /// Meshes the cap of plane i; false when the solid does not meet the plane.
  /// The cap of plane i within `segments` (its boundary vertices at their positions in the mesh, bit
  /// for bit); reads the mesh only.
  Mesh cap(int i, const FacetPolygon& facet, const std::vector<Edge>& segments) const {
    const HalfSpace& h = planes_[static_cast<std::size_t>(i)];
    const Vec3 normal(h.a, h.b, h.c);
    const Vec3 u = (std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(normal).normalized();
    const Vec3 v = normal.cross(u);
    const Vec3 origin = facet.corners.front();
    // The cap's own numbering: its boundary vertices, then the lattice inside.
    std::unordered_map<std::uint32_t, std::uint32_t> local;
    std::vector<std::uint32_t> global;
    planar::Region region;
    for (const Edge& s : segments) {
      Edge l{};
      for (int k = 0; k < 2; ++k) {
        const std::uint32_t g = s[static_cast<std::size_t>(k)];
        auto [it, added] = local.emplace(g, static_cast<std::uint32_t>(global.size()));
        if (added) {
          global.push_back(g);
          const Vec3 d = mesh_.positions[g] - origin;
          region.points.emplace_back(d.dot(u), d.dot(v));
        }
        l[static_cast<std::size_t>(k)] = it->second;
      }
      region.segments.push_back(l);
    }
    const std::vector<planar::Vec2> inner =
        planar::interior_lattice_points(region, edge_, kLatticeClearance * edge_);
    Mesh cap;
    for (std::uint32_t g : global) cap.positions.push_back(mesh_.positions[g]);
    for (const planar::Vec2& p : inner) cap.positions.push_back(origin + p.x() * u + p.y() * v);
    for (const auto& t : planar::triangulate_region(region, inner)) cap.triangles.push_back(t);
    const SurfacePtr plane = plane_surface(normal, -h.d, box_);
    clean_up(cap, *plane);
    // Boundary vertices are held by the clean-up, bit for bit.
    const std::unordered_map<Vec3, std::uint32_t, PositionHash> held = boundary_ids(segments);
    std::vector<bool> on_boundary(cap.positions.size());
    for (std::size_t k = 0; k < cap.positions.size(); ++k) on_boundary[k] = held.count(cap.positions[k]) > 0;
    open_narrow_corners(cap, *plane, on_boundary, kNarrowCorner, kSettle * tol_);
    return cap;
  }

  /// The ids of a cap's boundary vertices by their exact positions.
  std::unordered_map<Vec3, std::uint32_t, PositionHash> boundary_ids(
      const std::vector<Edge>& segments) const {
    std::unordered_map<Vec3, std::uint32_t, PositionHash> held;
    for (const Edge& s : segments)
      for (std::uint32_t g : s) held.emplace(mesh_.positions[g], g);
    return held;
  }

  /// Adds a cap to the mesh: its boundary vertices keep their ids, the others are new.
  void add_cap(const Mesh& cap, const std::vector<Edge>& segments) {
    const std::unordered_map<Vec3, std::uint32_t, PositionHash> held = boundary_ids(segments);
    std::vector<std::uint32_t> id(cap.positions.size());
    for (std::size_t k = 0; k < cap.positions.size(); ++k) {
      const auto it = held.find(cap.positions[k]);
      id[k] = it != held.end() ? it->second : add_vertex(cap.positions[k]);
    }
    for (const Triangle& t : cap.triangles) mesh_.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
  }

  /// The surface-bound clean-up on the cap's plane with its boundary held.
  void clean_up(Mesh& cap, const Surface& plane) const {
    RemeshSettings r = preset_remesh_settings(settings_, kDefaultRemeshIterations);
    r.sizes.largest = edge_;
    r.sizes.smallest = edge_;
    r.hold_cut = true;
    remesh_on_surface(cap, plane, r);
  }
};

}  // namespace

CapReport close_with_caps(Mesh& mesh, const Surface* smooth, const ConvexRegion& planes, std::size_t capped,
                          const Box& box, double edge, double tolerance, const Settings& settings,
                          bool narrow_corners) {
  return CapBuilder(mesh, smooth, planes, capped, box, edge, tolerance, settings, narrow_corners).run();
}

}  // namespace isopatch
