#pragma once
/// \file polyhedron_topology.hpp
/// The checks a closed polygon mesh (a control polyhedron, or a solid to be blended) must pass before
/// anything is built on it, and the cyclic order of the faces around each vertex.

#include <isopatch/geometry.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace isopatch {

/// Vertices and faces (0-based indices, counter-clockwise seen from outside).
struct PolygonMesh {
  std::vector<Vec3> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

/// What is wrong with a polygon mesh, and where: `face` is the 0-based face to blame, or nullopt
/// when the problem is a vertex's (`vertex`) or the whole mesh's.
struct TopologyProblem {
  std::optional<std::size_t> face;
  std::optional<std::size_t> vertex;
  std::string message;
};

/// The largest face a patch may have (the multi-sided Coons base takes up to 16 sides).
inline constexpr std::size_t kMaxFaceSides = 16;

/// The first problem found, or nullopt when the mesh is a closed, consistently oriented 2-manifold:
/// every face has 3..kMaxFaceSides distinct, in-range vertices and a non-zero area; every edge is used
/// by exactly two faces in opposite directions; the faces around every vertex form one cycle; every
/// vertex is used. The orientation itself (outward or inward) is not checked here (see signed_volume).
std::optional<TopologyProblem> find_topology_problem(const PolygonMesh& mesh);

/// Six times the signed volume enclosed (positive when the faces run counter-clockwise from outside).
double signed_volume(const PolygonMesh& mesh);

/// The (unnormalized) Newell normal of a face: its area vector, twice the area in length.
Vec3 newell_normal(const PolygonMesh& mesh, std::size_t face);

/// The faces around each vertex: neighbours[i] is the far end of edge i, faces[i] the face that holds
/// the half-edge (vertex -> neighbours[i]); the next edge is the one before the vertex in that face,
/// so faces[i-1] and faces[i] are the two faces of edge i, and the order is counter-clockwise seen
/// from outside. For a mesh that fails find_topology_problem a fan may stop early (open or
/// non-manifold); O(total face size log).
struct VertexFan {
  std::vector<std::uint32_t> neighbours;
  std::vector<std::uint32_t> faces;
};
std::vector<VertexFan> vertex_fans(const PolygonMesh& mesh);

/// Half-edge (a, b) -> (face, position of a in it). \pre a valid mesh.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>> half_edges(
    const PolygonMesh& mesh);

}  // namespace isopatch
