#pragma once
// Shapes made of surfaces that never meet, meshed one surface at a time: a sheet's two walls
// (sheet_meshing.hpp) and the two operands of a max or min whose surfaces stay apart (a lattice inside a
// curved skin, csg/apart_operands.hpp). Each surface goes through the whole entry point (mesh_surface),
// so that one with creases, a sheet or a capped lattice is meshed as such; the meshes are concatenated.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <span>

namespace isopatch {

/// Meshes one surface with settings (the full entry point, mesh_surface, so that a wall with creases
/// or a sheet of a sheet is meshed as such).
using WallMesher = std::function<Mesh(const Surface&, const Settings&, MeshStats*)>;

/// One surface of such a shape, and which of its mesh's components belong to the shape.
struct ApartSurface {
  SurfacePtr surface;
  SurfacePtr judge;   ///< null: every component kept; else only those where judge has...
  int keep_sign = 0;  ///< ...this sign (-1 or +1), read at the component's vertex farthest from judge = 0
};

/// Where surfaces must stay apart for the settings: the meshing box, or for a frame every rotation of it
/// about the origin (the cube around the origin that holds the box's farthest corner).
Box apart_domain(const Surface& f, const Settings& settings);

/// Each surface of `parts` meshed by `mesh_part` with the same settings (each later one with what the
/// earlier ones left of max_vertices, max_evaluations and time_limit), the components its judge rejects
/// dropped (their vertices too), and the meshes concatenated in order. A part that does not cross the
/// domain is left out. `stats` (may be null) gets the runs' counts added and stage times merged;
/// `surfaces`, when given, the number of parts that gave triangles.
/// \throw NoSurfaceError when no part crosses the domain or every component is dropped; whatever
///        `mesh_part` throws otherwise.
Mesh mesh_apart_surfaces(std::span<const ApartSurface> parts, const Settings& settings, MeshStats* stats,
                         const WallMesher& mesh_part, std::size_t* surfaces = nullptr);

/// When `f` is max(a, b) or min(a, b) with a = 0 and b = 0 apart throughout apart_domain() (proved down
/// to a quarter of the edge length, split_apart_operands()) and the method is Projection: a's components
/// inside b's solid (outside, for min) and b's inside a's (outside), each operand meshed by `mesh_part`
/// (mesh_apart_surfaces()). Returns nullopt for any other shape.
/// \throw as mesh_apart_surfaces().
std::optional<Mesh> mesh_apart_operands(const Surface& f, const Settings& settings, MeshStats* stats,
                                        const WallMesher& mesh_part);

}  // namespace isopatch
