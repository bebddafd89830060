#pragma once
/// \file crease_meshing.hpp
/// Formulas with creases (CSG shapes) meshed along them: the analysis of src/csg turns the shape into
/// a composite of disc-like pieces bounded by its exact creases and seams, which the composite path
/// meshes (projection, per-piece clean-up, multiresolution refinement). docs/creases.md.

#include <isopatch/composite_mesh.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <optional>

namespace isopatch {

/// The mesh of `surface` along its creases, or nullopt when it is not meshed that way: another method,
/// Creases::Off, a region, frame or given cells, not a formula, or no crease in the box.
/// \throw CreaseError when the shape has creases that cannot be meshed (docs/creases.md: solids touching
///        along an edge, a crease the tracer cannot follow); the
///        errors of mesh_composite().
std::optional<Mesh> mesh_along_creases(const Surface& surface, const Settings& settings, MeshStats* stats);

/// The composite path of mesh_composite() after its checks: projection along the composite's curves,
/// the clean-up per patch and the multiresolution refinement, in the settings' task arena.
Mesh mesh_composite_along_curves(const CompositeModel& model, const Settings& settings, MeshStats* stats);

}  // namespace isopatch
