#pragma once
/// \file raw_defects.hpp
/// Where the projection mesh is imperfect before any clean-up (issue "quality by construction"):
/// irregular vertices, small-angle triangles and short edges, counted by what made the vertex
/// (vertex_role.hpp): patch corners, seams (patch sides), patch interiors and fallback fans.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>

#include <vector>

namespace isopatch {

/// The defects of `mesh` (a closed or bounded mesh from the projection mesher) whose vertices have the
/// roles `roles` (role_value per vertex, the same length as mesh.positions). A vertex on an edge used
/// by one triangle is a boundary vertex and never counts as irregular. `size` is the target edge
/// length (edges under size / 5 count as short). \pre the mesh is valid, roles.size() matches.
RawDefects raw_defects(const Mesh& mesh, const std::vector<float>& roles, double size);

}  // namespace isopatch
