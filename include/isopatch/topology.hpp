#pragma once
/// \file topology.hpp
/// Combinatorial and topological checks of a triangle mesh: boundary and non-manifold edges,
/// non-manifold vertices, orientation consistency, degenerate triangles, duplicate and unreferenced
/// vertices, connected components with their Euler characteristic, genus and enclosed volume.
/// O(n log n) in the number of triangles (one sort of the half-edges), fine for millions of triangles.

#include <isopatch/mesh.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace isopatch {

/// One connected component (triangles linked through shared vertices).
struct ComponentTopology {
  std::size_t vertices = 0;  ///< referenced vertices of the component
  std::size_t edges = 0;
  std::size_t triangles = 0;
  std::size_t boundary_edges = 0;      ///< edges of exactly one triangle
  std::size_t boundary_loops = 0;      ///< connected groups of boundary edges
  std::size_t non_manifold_edges = 0;  ///< edges of three or more triangles
  std::size_t non_manifold_vertices = 0;
  std::size_t inconsistent_edges = 0;  ///< two triangles traverse the edge the same way
  long euler_characteristic = 0;       ///< V - E + F
  /// V - E + F = 2 - 2g - b (b boundary loops), when the component is a manifold consistently
  /// oriented surface; nullopt otherwise (or when the formula gives no whole non-negative g).
  std::optional<int> genus;
  /// Signed enclosed volume by the divergence theorem; positive for a closed outward-oriented
  /// component. Meaningless (origin-dependent) when the component has boundary edges.
  double volume = 0.0;
  /// Closed and oriented outward: positive volume where the winding number of the other closed
  /// components about it is 0, negative where it is 1 (the wall of a cavity faces into the cavity).
  /// With more than 64 closed components: positive volume.
  bool outward = false;

  bool closed() const { return boundary_edges == 0 && non_manifold_edges == 0; }
};

struct TopologyReport {
  std::size_t vertices = 0;   ///< all positions, referenced or not
  std::size_t edges = 0;      ///< distinct undirected edges of non-degenerate triangles
  std::size_t triangles = 0;  ///< all triangles
  std::size_t boundary_edges = 0;
  std::size_t non_manifold_edges = 0;
  /// Vertices whose incident triangles form more than one edge-connected fan (bow ties).
  std::size_t non_manifold_vertices = 0;
  std::size_t inconsistent_edges = 0;
  /// Triangles that repeat a vertex index (left out of every other count but `triangles`) or whose
  /// area is zero up to rounding (|e1 x e2| <= 1e-12 * longest edge^2; kept in the other counts).
  std::size_t degenerate_triangles = 0;
  std::size_t unreferenced_vertices = 0;
  /// Vertices at exactly the same position as another vertex of smaller index.
  std::size_t duplicate_vertices = 0;
  long euler_characteristic = 0;  ///< referenced V - E + F over the whole mesh
  /// Sum of the genera of the closed components that have one (see ComponentTopology::genus).
  int genus = 0;
  std::vector<ComponentTopology> components;  ///< in order of their first triangle

  /// No boundary and no non-manifold edge: every edge has exactly two triangles.
  bool watertight() const { return boundary_edges == 0 && non_manifold_edges == 0; }
  /// No non-manifold edge and no non-manifold vertex.
  bool manifold() const { return non_manifold_edges == 0 && non_manifold_vertices == 0; }
  /// Every edge of two triangles is traversed in opposite directions by them.
  bool consistently_oriented() const { return inconsistent_edges == 0; }
  /// Consistently oriented, and every closed component outward (ComponentTopology::outward).
  bool outward_oriented() const;
};

/// Analyses the connectivity of `mesh` (positions only matter for areas, duplicates and volumes).
/// \throw InputError if a triangle refers to a vertex out of range or a position is not finite.
TopologyReport analyze_topology(const Mesh& mesh);

}  // namespace isopatch
