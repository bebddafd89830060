#pragma once
/// \file composite_mesh_parts.hpp
/// A composite's mesh with what each element belongs to (its patch, its curve): what the composite
/// mesher (src/composite_mesher) makes and the measures of src/analysis read.

#include <isopatch/mesh.hpp>

#include <cstdint>
#include <vector>

namespace isopatch {

/// A composite's mesh with what each element belongs to.
struct CompositeMesh {
  Mesh mesh;
  /// Per vertex: the patch whose interior it lies in, or -1 for a vertex on a curve (a corner or a
  /// curve sample, shared by the patches that meet there). The first vertices are the curves'.
  std::vector<std::int32_t> vertex_patch;
  /// Per triangle: its patch.
  std::vector<std::uint32_t> triangle_patch;
  /// Per curve: the segments it was sampled with.
  std::vector<int> curve_segments;
  /// Per curve: its vertices from its start to its end (curve_segments + 1 of them; none for a curve
  /// no patch uses).
  std::vector<std::vector<std::uint32_t>> curve_vertices;
};

}  // namespace isopatch
