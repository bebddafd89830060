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

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "csg/crease_angle_repair.hpp"
#include "csg/csg_composite.hpp"

namespace isopatch {

/// What mesh_along_creases() did.
struct CreasedMesh {
  std::optional<Mesh> mesh;        ///< nullopt: mesh the surface as a smooth one
  bool creases_leave_box = false;  ///< why not, when it is because a crease leaves the box
};

/// The mesh of `surface` along its creases, or no mesh when it is not meshed that way: another method,
/// Creases::Off, a region, frame or given cells, not a formula, no crease in the box, or a crease that
/// leaves the box (said in the result: the caller warns after the smooth run, whose statistics replace
/// `stats`).
/// \throw CreaseError when the shape has creases that cannot be meshed (docs/creases.md: solids touching
///        along an edge, a crease the tracer cannot follow); the
///        errors of mesh_composite().
CreasedMesh mesh_along_creases(const Surface& surface, const Settings& settings, MeshStats* stats);

/// The crease analysis of `surface` as mesh_along_creases() makes it (src/csg: the composite of its
/// pieces and its face functions), or nullopt when it is not meshed along creases (see there;
/// `leaves_box`, when given, is set when a crease leaves the box).
/// \throw as mesh_along_creases().
std::optional<CsgShape> analyse_creases(const Surface& surface, const Settings& settings,
                                        std::optional<Vec3>* leaves_box = nullptr);

/// The last pass over a mesh along creases: triangles under the crease floor repaired on the shape's
/// face functions (csg/crease_angle_repair.hpp) with the tolerances relative to `box`'s diagonal;
/// vertices with `held` set stay.
AngleRepair repair_crease_angles(Mesh& mesh, const std::vector<SurfacePtr>& faces, const Box& box,
                                 const std::vector<std::uint8_t>* held = nullptr);

/// The composite path of mesh_composite() after its checks: projection along the composite's curves,
/// the clean-up per patch and the multiresolution refinement, in the settings' task arena. `finish`,
/// when given, is run on every refined mesh before the level is judged (a CSG shape's crease angle
/// repair: its refinement is kept on the angles the repair leaves, not those before it).
Mesh mesh_composite_along_curves(const CompositeModel& model, const Settings& settings, MeshStats* stats,
                                 const std::function<void(Mesh&)>& finish = {});

}  // namespace isopatch
