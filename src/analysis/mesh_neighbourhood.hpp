#pragma once
// Private helpers of the analysis module: input checks, distinct edges with their triangle counts,
// per-vertex valence and interior flags, area-weighted vertex normals and robust angles.

#include <isopatch/mesh.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

namespace isopatch::analysis {

/// \throw InputError (prefixed by `where`) for an index out of range or a non-finite position.
void check_mesh(const Mesh& mesh, const std::string& where);

inline bool repeats_vertex(const Triangle& t) {
  return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
}

struct Edge {
  std::uint32_t a = 0;          // smaller vertex index
  std::uint32_t b = 0;          // larger vertex index
  std::uint32_t triangles = 0;  // number of triangles containing the edge
};

struct MeshNeighbourhood {
  std::vector<Edge> edges;  // distinct edges of the triangles that repeat no index, sorted by (a, b)
  std::vector<std::uint32_t> valence;  // distinct neighbours per vertex
  std::vector<bool> referenced;        // in at least one triangle that repeats no index
  // Referenced, and every edge at the vertex is shared by exactly two triangles.
  std::vector<bool> interior;
};

/// O(F log F): one sort of the 3F half-edge keys. \pre check_mesh passed.
MeshNeighbourhood mesh_neighbourhood(const Mesh& mesh);

/// Sum over the incident triangles of (b - a) x (c - a), i.e. twice the area-weighted normal; zero for
/// unreferenced vertices. \pre check_mesh passed.
std::vector<Vec3> area_weighted_normals(const Mesh& mesh);

/// Angle between u and v in radians, in [0, pi], accurate near 0 and pi (atan2 of |u x v| and u . v);
/// 0 when either vector is zero.
inline double angle_between(const Vec3& u, const Vec3& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// The smallest angle of triangle p0 p1 p2 in degrees; 0 for a triangle of zero area.
inline double smallest_angle_degrees(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  if (!((p1 - p0).cross(p2 - p0).norm() > 0.0)) return 0.0;
  const double smallest = std::min(
      {angle_between(p1 - p0, p2 - p0), angle_between(p2 - p1, p0 - p1), angle_between(p0 - p2, p1 - p2)});
  return smallest * 180.0 / std::numbers::pi;
}

}  // namespace isopatch::analysis
