#pragma once
/// \file settings.hpp
/// One Settings struct for every mesher, composed of the settings of each stage (stage_settings.hpp),
/// each field with its documented default, and the statistics a mesher reports back (mesh_stats.hpp).

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
struct Settings : SizeSettings,
                  OctreeSettings,
                  PatchSettings,
                  ProjectionSettings,
                  MarchingCubesSettings,
                  CleanupSettings,
                  BudgetSettings {
  Method method = Method::Projection;
  /// The region to mesh; the surface's default box when empty. Must be valid().
  std::optional<Box> box;

  /// Checks every stage's settings and the box. \throw SettingError naming the first field out of range.
  void validate() const;
};

}  // namespace isopatch
