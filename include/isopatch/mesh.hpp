#pragma once
/// \file mesh.hpp
/// A data-oriented triangle mesh: positions and triangles as flat arrays, with named per-vertex float
/// attributes beside them (curvature, distance error, ...). Adjacency is built only by the algorithms
/// that need it. Triangles are counter-clockwise seen from outside (normal along grad f).

#include <isopatch/geometry.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace isopatch {

using Triangle = std::array<std::uint32_t, 3>;

/// A named per-vertex attribute; values.size() equals the vertex count of its mesh.
struct VertexAttribute {
  std::string name;
  std::vector<float> values;
};

struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<VertexAttribute> attributes;  ///< in insertion order

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return triangles.size(); }

  /// Adds the attribute, or replaces the one of the same name.
  /// \throw InputError if values.size() != vertex_count() or the name is empty or not an identifier
  ///        ([A-Za-z_][A-Za-z0-9_]*).
  void set_attribute(const std::string& name, std::vector<float> values);
  /// The attribute's values, or nullptr when there is none of that name.
  const std::vector<float>* find_attribute(const std::string& name) const;

  /// Checks that every index is in range, no triangle repeats a vertex, every position is finite and
  /// every attribute has one value per vertex. \throw InputError naming the first violation.
  void validate() const;
};

/// Axis-aligned bounding box of the positions (an invalid Box for an empty mesh).
Box bounding_box(const Mesh& mesh);

/// Unit area-weighted vertex normals (the sum of the incident triangles' cross products, normalized),
/// along the mesh's own orientation; the zero vector at a vertex with no non-degenerate incident
/// triangle. \pre every index is in range.
std::vector<Vec3> vertex_normals(const Mesh& mesh);

}  // namespace isopatch
