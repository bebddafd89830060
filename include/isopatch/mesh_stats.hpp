#pragma once
/// \file mesh_stats.hpp
/// What a mesher did, typed: one struct per stage (the projection mesher, marching cubes, fairing, the
/// clean-up) and one for what the mesh written may get wrong (warnings). A stage that did not run
/// leaves its part empty. visit_stats() lists every number by a stable name, for printing and JSON.

#include <isopatch/geometry.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace isopatch {

/// Wall time of each stage of a run, by stable names in the order the stages first ran; a stage that
/// runs several times (a refinement round, a clean-up round) adds up. Names: "partition", "sides",
/// "patches", "checks", "defects" (the projection mesher), "marching_cubes", "fairing", and "cleanup_<pass>"
/// ("cleanup_setup", "cleanup_split", "cleanup_collapse", "cleanup_flip", "cleanup_relax",
/// "cleanup_repair", "cleanup_valence_search", "cleanup_curvature", "cleanup_error_bound",
/// "cleanup_local" for the preview's local repair).
struct StageTimes {
  std::vector<std::pair<std::string, double>> seconds;
  /// Adds `s` seconds to `stage` (appended when new).
  void add(std::string_view stage, double s);
  /// Adds every stage of `other`.
  void merge(const StageTimes& other);
  /// The seconds of `stage`, 0 when it did not run.
  double of(std::string_view stage) const;
};

/// Where the projection mesh (before any clean-up) is imperfect, by what made the vertex: patch corners
/// (edge crossings of the partition), the seams between patches (side vertices), patch interiors and
/// centres, and the fans that close cells without a patch. A triangle counts for the most
/// seam-like of its vertices (fan > corner > seam > interior). Filled when vertex roles were kept.
struct RawDefects {
  /// Indices: 0 corner, 1 seam, 2 interior (centre included), 3 fan.
  static constexpr int kKinds = 4;
  std::size_t vertices[kKinds] = {};
  std::size_t irregular_vertices[kKinds] = {};  ///< interior vertices of valence other than 6
  std::size_t triangles[kKinds] = {};
  std::size_t triangles_under_20[kKinds] = {};  ///< smallest angle below 20 degrees
  std::size_t triangles_under_10[kKinds] = {};
  std::size_t short_edges = 0;  ///< edges shorter than a fifth of the target size
  static constexpr const char* kNames[kKinds] = {"corner", "seam", "interior", "fan"};
};

/// The projection mesher (projection.hpp).
struct ProjectionStats {
  int start_depth = 0;                          ///< octree depth the surface cells started at
  int depth_limit = 0;                          ///< the deepest level cells could be refined to
  int resolution = 0;                           ///< Settings::resolution (0: per side, see side_segments_*)
  int side_segments_min = 0;                    ///< fewest segments of any patch side
  int side_segments_max = 0;                    ///< most segments of any patch side
  std::map<int, std::size_t> patches_by_sides;  ///< accepted patches by their number of sides
  std::size_t rejected_patches = 0;             ///< patches rejected over all refinement rounds
  std::size_t rejected_sides = 0;               ///< sides rejected over all refinement rounds
  std::size_t refined_patches = 0;              ///< patches of cells deeper than the starting depth
  std::size_t fallback_cells = 0;               ///< cells closed by fans instead of a patch
  std::size_t unprojected_vertices = 0;         ///< fan centres that no ray brought onto f = 0
  std::size_t gradient_rays = 0;                ///< interior vertices marched along grad f instead of d(x)
  std::size_t clamped_base_points = 0;          ///< base points outside their cell, moved into it
  std::size_t refinements = 0;                  ///< rounds of local refinement
  std::size_t curvature_depth_steps = 0;        ///< levels the start went deeper for the curvature
  std::size_t flat_corner_cells = 0;            ///< cells with a corner inside one of their faces
  std::map<int, std::size_t> cells_by_depth;    ///< surface cells of the final partition by depth
  bool coons_base = false;                      ///< the multi-sided Coons base was used
  std::optional<RawDefects> defects;            ///< of the mesh before the clean-up (vertex roles kept)
};

/// Marching cubes (marching_cubes.hpp).
struct MarchingCubesStats {
  std::uint64_t cells = 0;  ///< grid cells
  double cell_size = 0.0;   ///< side of a grid cell
};

/// Laplace fairing after marching cubes (fairing.hpp).
struct FairingSummary {
  int iterations = 0;
  std::size_t unconverged = 0;  ///< vertex projections that did not converge
};

/// The surface-bound clean-up (remesh.hpp remesh_on_surface).
struct RemeshStats {
  int iterations = 0;  ///< rounds of split / collapse / flip / relax run
  std::size_t splits = 0;
  std::size_t collapses = 0;
  std::size_t flips = 0;
  std::size_t repairs = 0;          ///< small-angle triangles removed by the final pass
  std::size_t rejected_moves = 0;   ///< relaxation moves skipped (fold, projection failure, box)
  std::size_t exactness_moves = 0;  ///< vertex moves kept by the curvature sweeps
  /// With max_error: triangles whose centroid is still farther than max_error from f = 0 at the end
  /// (after the splits that enforce the bound).
  std::size_t error_bound_violations = 0;
  std::uint64_t gradient_evaluations = 0;
  std::uint64_t hessian_evaluations = 0;
  StageTimes times;  ///< per pass, "cleanup_<pass>" (StageTimes)

  /// Adds the counts of another clean-up run (iterations: the larger; times are not merged: callers
  /// time their runs as a whole or merge StageTimes themselves).
  void add_counts(const RemeshStats& o) {
    iterations = iterations > o.iterations ? iterations : o.iterations;
    splits += o.splits;
    collapses += o.collapses;
    flips += o.flips;
    repairs += o.repairs;
    rejected_moves += o.rejected_moves;
    exactness_moves += o.exactness_moves;
    error_bound_violations += o.error_bound_violations;
    gradient_evaluations += o.gradient_evaluations;
    hessian_evaluations += o.hessian_evaluations;
  }
};

/// What the mesh written may get wrong, for warnings.
struct MeshWarnings {
  /// Cells still in doubt at the depth limit (two loops, an ambiguous face, an edge crossed twice, a
  /// loop against the gradients, no loop), by reason ("several-loops", "ambiguous-face", ...).
  std::map<std::string, std::size_t> doubtful_cells_by_reason;
  std::size_t doubtful_cells = 0;
  /// Of those, the cells that put the topology in question: sheets closer than such a cell may be
  /// joined or dropped there.
  std::size_t doubtful_topology_cells = 0;
  /// Cells whose ambiguous faces the surface only grazes (not counted as topology in doubt).
  std::size_t doubtful_grazing_faces = 0;
  double doubtful_cell_size = 0.0;  ///< side of the largest doubtful cell
  int depth_limit = 0;              ///< the depth those cells are at
  /// With Settings::max_error: triangles whose centroid is still beyond the bound.
  std::optional<std::size_t> error_bound_violations;
  /// Composite surfaces: patches still rejected after their curves were refined, closed by a fan over
  /// their boundary, and the fan centres of those that no ray brought onto the patch's function.
  std::size_t fan_patches = 0;
  std::size_t unprojected_fan_centres = 0;
  /// CSG shapes: corners of pieces sharper than the 25 degree angle floor (two faces or creases meet
  /// at a smaller angle there), where triangles cannot reach the floor.
  std::size_t exempt_corners = 0;
  /// CSG shapes: cells where interval arithmetic cannot rule out a crease but none was found (one may
  /// be missing there: a feature far smaller than an edge, or faces meeting along a sheet).
  std::size_t uncertain_crease_cells = 0;
  Vec3 uncertain_crease_near = Vec3::Zero();  ///< the centre of the first of them
  /// CSG shapes: 1 when a crease leaves the box and the shape cut open by the box could not be meshed
  /// along its creases, so it was meshed as a smooth surface.
  std::size_t creases_leave_box = 0;
  /// CSG shapes: 1 when a formula with creases was meshed through the partition as a smooth surface:
  /// given cells, or a region whose cut could not be meshed along the creases (docs/creases.md).
  std::size_t creases_in_partition = 0;
  /// CSG shapes (Creases::Automatic): 1 when the crease paths could not mesh the shape (a face they cannot
  /// cut into pieces, a feature at the edge's scale), so it was meshed as a smooth surface with its creases
  /// rounded; `crease_failure` says why and where (Creases::Exact refuses with that message instead).
  std::size_t creases_rounded = 0;
  std::string crease_failure;
  /// CSG shapes: the edge length (half the one asked for) at which the shape, or one of its parts (a
  /// sheet's wall, an operand), was meshed along its creases after the crease paths failed at the edge
  /// asked for on a feature at the edge's scale (`crease_failure` says where); 0 when none was.
  double creases_finer_edge = 0.0;
  /// Pairs of triangles that cross (self_intersection.hpp; at most 1000 counted), and a point where the
  /// first pair meets. The meshers do not look for them: the front ends (the command line, the Python
  /// package) run the exact check on every mesh they return and fill these.
  std::size_t self_intersecting_pairs = 0;
  Vec3 self_intersection_near = Vec3::Zero();
};

/// What the crease analysis of a CSG shape found (Settings::creases, docs/creases.md).
struct CreaseStats {
  std::size_t faces = 0;         ///< smooth faces (the sides of a smooth blend count as one)
  std::size_t creases = 0;       ///< crease curves traced
  std::size_t corners = 0;       ///< points where three or more faces meet
  std::size_t seams = 0;         ///< seams cutting faces into disc-like pieces
  std::size_t pieces = 0;        ///< patches meshed
  std::size_t smooth_pairs = 0;  ///< pairs of faces that meet without a crease (merged)
  std::size_t repair_moves = 0;  ///< vertex moves of the last pass over small angles (seams, creases)
  /// Interval analysis: cells of the cover where two faces may meet (every crease passes through
  /// them), creases traced from those cells that the seed grid missed, and cells nothing explained.
  std::size_t interval_cells = 0;
  std::size_t interval_creases = 0;
  std::size_t uncertain_cells = 0;
  /// A smooth solid capped by a convex polyhedron (max(g, planes): a capped lattice): planar caps meshed
  /// and the vertices on the creases (on g = 0 and a plane, or on two planes); 0 on the general path.
  std::size_t caps = 0;
  std::size_t crease_vertices = 0;
  /// Planes that cut the shape open (a region's, the box's where the shape leaves it): the shape meshed
  /// as its intersection with them, their caps taken away (docs/creases.md, "Cut open").
  std::size_t cut_planes = 0;
  double seconds = 0.0;  ///< of the analysis
};

/// What multiresolution meshing did (RefineSettings): the level used and what its base was.
struct RefineStats {
  int level = 1;                     ///< k of the output (1: the base is the output)
  int first_level = 1;               ///< the first level tried
  int attempts = 0;                  ///< bases meshed (a failed guard or a curvature step adds one)
  double target_edge = 0.0;          ///< h, the target (largest) edge length
  double largest_curvature = 0.0;    ///< over the first base's vertices (automatic level)
  double estimated_curvature = 0.0;  ///< the coarse grid's first guess of it (automatic level)
  std::size_t base_vertices = 0;
  std::size_t base_triangles = 0;
  std::size_t failed_points = 0;           ///< of the refinements given up (their level halved)
  std::size_t rejected_moves = 0;          ///< relaxation moves undone
  std::size_t angle_vertices = 0;          ///< vertices of the sweeps aimed at small angles
  std::size_t repaired_vertices = 0;       ///< moves that raised the smallest angle around a vertex
  double smallest_angle = 0.0;             ///< after the refinement, degrees
  std::uint64_t gradient_evaluations = 0;  ///< of the refinement alone
};

/// Sizes refined locally where the box or a region plane cuts f = 0 in features smaller than an edge, or
/// where f = 0 turns within an edge (SizeSettings::uniform, docs/algorithms.md 4.11 and 4.12).
struct LocalSizes {
  std::size_t sources = 0;            ///< points of the cut curves that asked for a smaller size
  std::size_t curvature_sources = 0;  ///< points where f = 0 turns within an edge (a thin rim, a tube)
  std::size_t around = 0;             ///< points of SizeSettings::refine_around in the box
  double smallest_size = 0.0;         ///< the smallest size they asked for
  Box extent;                         ///< the bounding box of those points
  std::size_t added_vertices = 0;     ///< about how many vertices the smaller sizes added to the output
};

/// A sheet (f = phi(|g|), the wall of a lattice) meshed as its two walls (docs/lattices.md, "Sheets").
struct SheetStats {
  /// Walls meshed: 2, 1 when the other does not cross the box, more for a sheet of a sheet
  /// (abs(abs(g) - a) - t has four).
  std::size_t walls = 0;
};

struct MeshStats {
  double seconds = 0.0;
  int threads = 1;                         ///< worker threads the run used
  std::uint64_t value_evaluations = 0;     ///< evaluations of f alone
  std::uint64_t gradient_evaluations = 0;  ///< evaluations of f with its gradient
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::optional<ProjectionStats> projection;
  std::optional<MarchingCubesStats> marching_cubes;
  std::optional<FairingSummary> fairing;
  std::optional<RemeshStats> cleanup;
  std::optional<RefineStats> refine;  ///< multiresolution meshing, when it ran
  std::optional<LocalSizes> local_sizes;
  std::optional<CreaseStats> creases;  ///< when the shape was meshed along its creases
  std::optional<SheetStats> sheet;     ///< when a sheet was meshed as its two walls
  MeshWarnings warnings;
  StageTimes times;  ///< wall time per stage
};

/// Calls `visit(stage, name, value)` for every number of `stats` whose stage ran, in a fixed order:
/// stage "mesh" (seconds, threads, evaluations, evaluations per output vertex, vertices, triangles),
/// then "seconds" (StageTimes), "projection" (with "defect_<kind>_<what>" from RawDefects),
/// "marching_cubes", "fairing", "cleanup", "refine", "local_sizes", "creases", "sheet", "warnings". Names are
/// stable (scripts read them): per-count families are spelled "patches_N", "leaves_depth_N",
/// "doubtful_REASON".
void visit_stats(
    const MeshStats& stats,
    const std::function<void(std::string_view stage, std::string_view name, double value)>& visit);

}  // namespace isopatch
