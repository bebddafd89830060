#pragma once
/// \file remesh.hpp
/// Surface-bound clean-up of a triangle mesh of f = 0: isotropic remeshing in the manner of Botsch &
/// Kobbelt 2004 ("A remeshing approach to multiresolution modeling", SGP) restricted to the implicit
/// surface: long edges are split, short edges collapsed, edges flipped towards valence 6 (4 on the
/// boundary; greedy flips, then glide chains of energy-neutral flips that move irregular vertex pairs
/// until they cancel, after Surazhsky & Gotsman 2003), vertices relaxed tangentially and every moved or new
/// vertex projected back onto f = 0 by Newton steps along grad f, so vertices stay on the surface. A final
/// pass removes the remaining triangles with a small angle (flip of the longest edge, else collapse of the
/// shortest).
///
/// On a mesh from the projection mesher, which is regular inside its patches, the operations act
/// almost only along patch seams and in tiny corner patches (docs/algorithms.md 5): see
/// docs/whole-surface-quality.md for the measurements against the alternatives.
///
/// Sizes: a uniform target edge length, or a curvature-adapted size field for a chordal error bound
/// (size_for_error in curvature.hpp), graded so that sizes at neighbouring vertices differ by a bounded
/// factor. Where the surface is cut open by its box (settings.box), the cut stays on the box: a cut
/// vertex on one box face slides along the curve where f = 0 meets that face and may be merged into
/// its neighbour on the cut; those on box edges and corners, and every boundary without a box, stay.

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/stage_settings.hpp>
#include <isopatch/surface.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

namespace isopatch {

struct RemeshSettings {
  /// The target sizes, the same description the projection mesher follows (stage_settings.hpp):
  ///   sizes.largest: the target edge length h (uniform sizes), or the largest size when sizes vary;
  ///     must be > 0;
  ///   sizes.max_error (> 0): sizes from the analytic curvature so that the distance of triangle
  ///     centroids from f = 0 stays below this bound (size_for_error), clamped to [smallest, largest];
  ///   sizes.user: a size of the caller's own at a point (> 0); the size is the smallest of this, the
  ///     curvature size and largest, and at least smallest; graded like the curvature sizes;
  ///   sizes.smallest: the floor of varying sizes (near singular points); > 0 and <= largest when
  ///     sizes vary.
  TargetSizes sizes;
  /// Largest ratio between the sizes at the two ends of an edge, relative to the edge length:
  /// h(v) <= h(u) + grading * |u - v|. In (0, 1].
  double grading = 0.3;
  /// What the clean-up does: the same settings a whole meshing run takes (stage_settings.hpp), so a
  /// preset means the same passes everywhere (docs/algorithms.md 5.3):
  ///   cleanup.remesh_iterations: rounds of split / collapse / flip / relax, 0..100; empty:
  ///     kDefaultRemeshIterations; 0 leaves the mesh unchanged;
  ///   cleanup.quality: Default, the rounds, then the repairs, the valence search, 8 rounds of final
  ///     relaxation (docs/whole-surface-quality.md: they lower the mean-curvature error by 10-45% for
  ///     about a fifth more time) and the curvature sweeps; Preview, the local repair instead (short
  ///     edges collapsed, small angles repaired, valences flipped, only the vertices within two rings of
  ///     a defect relaxed, one sweep of borrowing chains; no curvature sweeps; cost in proportion to the
  ///     defects); Fine, Default with twice the valence search and curvature sweeps (within their
  ///     bounds) and 12 final relaxation rounds;
  ///   cleanup.valence_search: flips tried per chain in the final sweep whose chains may borrow energy
  ///     to pull apart the 5-7 pairs left side by side, 0..kMaxValenceSearch; 0 skips that sweep;
  ///   cleanup.curvature_sweeps: Gauss-Seidel sweeps of tangential moves that make the cotangent
  ///     Laplacian exact for quadratics at every vertex (lower discrete-curvature error),
  ///     0..kMaxCurvatureSweeps; 0 skips them.
  CleanupSettings cleanup;
  /// Vertices never leave this box (moves that would are skipped). Empty: no constraint.
  std::optional<Box> box;
  /// The planes of a region that cut the surface open (Settings::region): vertices stay inside them; a
  /// cut vertex on exactly one of them (and on no box face) slides along it, like one on a box face.
  ConvexRegion cut_planes;
  /// When true, the cut stays exactly where it is: no boundary vertex slides along a box face or region
  /// plane, nor merges into a neighbour (a tile's boundary, shared with the tile across, is given data).
  bool hold_cut = false;
  /// When set and true, stops with LimitError("cancelled") at the next check.
  const std::atomic<bool>* cancel = nullptr;
  /// Called at the start of each round and pass with Progress::stage "cleanup"; may be empty.
  std::function<void(const Progress&)> progress;
};

// RemeshStats, what remesh_on_surface() did, is in mesh_stats.hpp (it is also MeshStats::cleanup).

/// Remeshes `mesh`, a mesh of `surface` (vertices on f = 0, triangles oriented along grad f), in place.
/// Per-vertex attributes are carried over for surviving vertices; vertices created by splits take the
/// value of the first edge end, except for an attribute named "role", where they get 5.
/// The passes run are those of the plan for these settings (src/remesh/cleanup_plan.hpp).
/// \throw InputError for invalid settings (SettingError naming the field); EvaluationError if f or its
/// derivatives are not finite at a
///        vertex; LimitError("cancelled"). After an exception from the remeshing itself (not from the
///        checks of the settings and the mesh), `mesh` is left empty: it is held once, not twice.
RemeshStats remesh_on_surface(Mesh& mesh, const Surface& surface, const RemeshSettings& settings);

}  // namespace isopatch
