#pragma once
/// \file settings.hpp
/// One Settings struct for every mesher, composed of the settings of each stage (stage_settings.hpp),
/// each field with its documented default, and the statistics a mesher reports back (mesh_stats.hpp).

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/stage_settings.hpp>

#include <optional>

namespace isopatch {

enum class Method {
  Projection,     ///< the paper's method (default)
  MarchingCubes,  ///< Lorensen & Cline 1987 baseline
};

/// Every setting of every mesher: the stage settings (stage_settings.hpp), each read only by its
/// stage, with the method and the region. Fields are reached directly (settings.edge_length).
/// How formulas with creases (min, max, abs: CSG shapes) are meshed.
enum class Creases {
  Automatic,  ///< along their creases when a formula has real ones (docs/creases.md); else as smooth; where
              ///< the crease paths cannot mesh the shape, as smooth with a warning (warnings.creases_rounded)
  Off,        ///< as a smooth surface (creases rounded off by the projection, as before)
  Exact,      ///< as Automatic, but a shape whose creases cannot be meshed is refused (CreaseError)
};

/// "auto", "off" or "exact". \throw SettingError (setting "creases") otherwise.
Creases parse_creases(const std::string& name);

struct Settings : SizeSettings,
                  OctreeSettings,
                  PatchSettings,
                  ProjectionSettings,
                  MarchingCubesSettings,
                  CleanupSettings,
                  RefineSettings,
                  BudgetSettings {
  Method method = Method::Projection;
  /// Projection only, formulas only, without given cells: CSG shapes meshed along their exact creases
  /// and corners (Automatic; a region or the box cuts them open along exact curves, a frame leaves the
  /// crease mesh as it is: docs/creases.md), or as smooth surfaces (Off).
  Creases creases = Creases::Automatic;
  /// The region to mesh; the surface's default box when empty. Must be valid().
  std::optional<Box> box;
  /// Projection only. A convex polytope to mesh inside (inside the box when one is given; else instead
  /// of it when bounded, and inside the surface's own box when not): the partition is the lattice of
  /// cubes clipped by its planes, and where the surface leaves the region its boundary lies on the
  /// planes. Empty: the box alone.
  ConvexRegion region;
  /// Projection only. The partition in a rotated frame (the surface, box and region are seen in it;
  /// the mesh comes back in the user's coordinates). Empty: the coordinate axes.
  std::optional<Frame> frame;
  /// Projection only. A partition of convex cells given directly, each cell the intersection of its
  /// half-spaces (within the box, when one is given); checked for overlaps and gaps. Cells that fail are
  /// split by three planes through the centre of their bounds. Empty: the octree (or the region).
  std::vector<ConvexRegion> cells;

  /// Checks every stage's settings and the box. \throw SettingError naming the first field out of range.
  void validate() const;
};

}  // namespace isopatch
