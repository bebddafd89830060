#pragma once
// What the viewer shows: a mesh with its per-vertex fields, its summary for the page, and its GLB.

#include <isopatch/error.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <nlohmann/json.hpp>

#include <atomic>
#include <string>

#include "view/view_request.hpp"

namespace isopatch::view {

// The implicit noexcept move calls nlohmann::json's assert_invariant, which clang-tidy cannot prove
// does not throw (it only asserts):
// NOLINTNEXTLINE(bugprone-exception-escape)
struct ViewMesh {
  Mesh mesh;               ///< with the fields as vertex attributes
  nlohmann::json summary;  ///< what the page prints: name, counts, time, valence-6 share, smallest angle
  std::string glb;         ///< the mesh as .glb, COLOR_0 = mean curvature (mesh_io.hpp)
};

/// Meshes `request` through the library (resolve_surface, mesh_surface with request.settings and
/// `cancel`), attaches the curvature and distance fields against the surface (attach_fields) and
/// measures the result (analyze_shape, analyze_valence).
/// \throw whatever resolve_surface and mesh_surface throw (ParseError, LimitError, ...).
ViewMesh mesh_request(const MeshRequest& request, const std::atomic<bool>* cancel);

/// A mesh read from a file, shown as it is: fields against `surface` when given (attach_fields),
/// else the discrete mean and Gaussian curvature, unless the mesh already carries those attributes.
/// \throw InputError as discrete_curvature and encode_mesh (a mesh without triangles).
ViewMesh view_mesh_file(Mesh mesh, const std::string& name, const Surface* surface);

/// The page's view of an error: {"error": message, "kind": ..., "setting": ...} and, for a ParseError,
/// "line", "column" (1-based) and "excerpt" (the line and a caret).
nlohmann::json error_json(const Error& error);

}  // namespace isopatch::view
