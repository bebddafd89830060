#pragma once
// A sheet, f = phi(|g|) (the wall of a lattice, abs(gyroid) - t), meshed as its two walls, each a
// smooth surface of its own (csg/sheet_shape.hpp): the partition's cells then follow one wall at a time,
// whatever the sheet's thickness against the edge, instead of having to separate two walls closer than
// an edge (docs/lattices.md, "Sheets").

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include "api/apart_meshing.hpp"

#include <array>
#include <optional>

namespace isopatch {

/// The two walls mesh_sheet() meshes `f` as (split_sheet_shape() over the box, or every rotation of it
/// in a frame), or nullopt when f is not such a sheet there or the method is not the projection.
std::optional<std::array<SurfacePtr, 2>> sheet_walls(const Surface& f, const Settings& settings);

/// When `f` is a sheet whose walls stay apart throughout the domain of `settings` (its box, region,
/// cells, or every rotation of its box for a frame) and the method is Projection: each wall meshed by
/// `mesh_wall` as mesh_apart_surfaces() meshes its parts (first wall's vertices first); `stats` (may
/// be null) as there, and `sheet` set. Returns nullopt when `f` is not such a sheet.
/// \throw NoSurfaceError when neither wall crosses the domain; whatever `mesh_wall` throws otherwise.
std::optional<Mesh> mesh_sheet(const Surface& f, const Settings& settings, MeshStats* stats,
                               const WallMesher& mesh_wall);

}  // namespace isopatch
