#pragma once
/// \file composite_mesh.hpp
/// Composite implicit surfaces: patches, each the zero set of its own function inside its own region of
/// space, meeting along boundary curves known from their construction, such as the I-patches of a
/// control polyhedron (Sipos, Varady, Salvi & Vaitkus 2020; Varady, Benko, Kos & Rockwood 2001) and
/// setback vertex blends (Varady & Rockwood 1997), read from `.ipatch` files. Meshed by projection as
/// Sipos & Salvi 2021, sec. 4, do: the known curves sampled once and shared by both patches (watertight
/// without welding), the multi-sided C0 Coons patch over them, projection onto each patch's own
/// function inside its region; or by Marching Cubes on the piecewise function (the patch whose region
/// holds a point most deeply), for comparison.

#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch {

struct Composite;  // the description itself (library internal)

/// A composite surface ready to mesh, render and analyse.
class CompositeModel {
 public:
  /// \throw InputError when the composite is empty or has no valid box (see CompositeSurface).
  explicit CompositeModel(std::shared_ptr<const Composite> composite);

  /// The composite as one Surface: at x, the function of the patch whose region holds x most deeply.
  const SurfacePtr& surface() const { return surface_; }
  const Composite& composite() const { return *composite_; }
  std::size_t patch_count() const;
  /// One line per defect the validity check finds in a patch function (an extra sheet in its region, a
  /// bulge above a face plane, a fold or a sharp bend beside its boundary): such a patch is likely
  /// rejected by projection and closed by a fan. Empty when every patch passes. Deterministic.
  std::vector<std::string> shape_warnings() const;

 private:
  std::shared_ptr<const Composite> composite_;
  SurfacePtr surface_;
};

/// Reads a `.ipatch` file (docs/ipatch.md): a control polyhedron, or a solid with setback vertex blends.
/// \throw IoError when it cannot be read; InputError "<file>:<line>:<column>: <what>" for malformed
///        text or topology, "<file>: <what>" for geometry the construction refuses.
CompositeModel read_composite(const std::string& path);
/// The same for text in memory; `source_name` names it in errors. \throw InputError as read_composite.
CompositeModel parse_composite(std::string_view text, std::string_view source_name);

/// Whether `path` names a composite file (it ends in ".ipatch").
bool is_composite_path(std::string_view path);

/// Whether mesh_composite() meshes with these settings through the partition (mesh_surface() on the
/// piecewise function) instead of the construction's curves: when a region, a frame or given cells are
/// set (they describe a partition, which the construction's curves do not have).
bool meshed_through_partition(const Settings& settings);

/// Meshes the composite with settings.method:
///   Projection: every curve sampled once (its length over the target edge length, 1..64 segments, or
///     settings.resolution), a base patch per patch (settings.base: Automatic and Coons, the Coons patch
///     over its curves; Barycentric, the combination of its corners) projected onto its function
///     inside its region, rejected patches' curves refined (at most refinement_levels rounds; then a
///     fan, counted in stats.projection.fallback_cells), then each patch cleaned up on its own function
///     with its boundary fixed (remesh_iterations, quality; 0 iterations: the paper's method alone).
///     Every vertex lies on the function of each patch it belongs to. With a region, a frame or given
///     cells (meshed_through_partition()): mesh_surface() on model.surface(), the piecewise function
///     meshed through the octree or the convex cells, clipped by the region; every vertex then lies on
///     the function of the patch whose region holds it most deeply, and seams are not held as curves.
///     The octree's settings (min_depth, max_depth, max_cell_curvature, refine_around) have no meaning
///     along the curves: set to other than their defaults without a region, frame or cells, they are
///     refused (SettingError naming the field), never ignored.
///   MarchingCubes: mesh_surface() on model.surface() (grid, fairing and clean-up as for formulas).
/// Budgets (max_evaluations, time_limit, max_vertices, cancel) and threads as in mesh_surface(); the
/// same mesh for any thread count. Fills `stats` when given.
/// \throw SettingError for settings out of range or octree settings on the curve path; InputError for an
///        inconsistent composite (sides that do not close, a
///        curve used twice the same way); EvaluationError; LimitError.
Mesh mesh_composite(const CompositeModel& model, const Settings& settings, MeshStats* stats = nullptr);

}  // namespace isopatch
