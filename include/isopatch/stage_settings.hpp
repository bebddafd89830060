#pragma once
/// \file stage_settings.hpp
/// The settings of each stage of the pipeline, each with its documented defaults and its own
/// validate(): target sizes (shared by the projection mesher and the clean-up), the octree, the
/// patches, the projection, marching cubes, the clean-up, and the budgets. Settings (settings.hpp)
/// composes them; each stage reads only its own. validate() throws SettingError naming the field.

#include <isopatch/geometry.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace isopatch {

/// Target edge lengths, shared by the projection mesher (cell sizes, segments per side) and the
/// clean-up (split and collapse thresholds).
struct SizeSettings {
  /// Target edge length of the output (with max_error or size_field: the largest). Empty: the longest
  /// box side / 64 (/ 16 with max_error or a size_field). Must be > 0.
  std::optional<double> edge_length;
  /// When set: a curvature-adapted size field keeps the distance of triangle centroids from f = 0 below
  /// this bound (edge lengths sqrt(3 eps / kappa_max), at most edge_length, graded); the projection
  /// octree refines where the field asks for smaller cells. Must be > 0.
  std::optional<double> max_error;
  /// A size field of your own (library only): the target edge length at a point, > 0 and finite. When
  /// set it replaces edge_length as the target (edge_length, or the longest box side / 16, then caps
  /// it, and 1/2048 of the longest side is the floor); the projection octree refines where it asks for
  /// smaller cells, and the clean-up grades and follows it. Combined with max_error, the smaller wins.
  std::function<double(const Vec3&)> size_field;
  /// With size_field: the smallest size it asks for. The floor of the target sizes becomes the smaller
  /// of it and 1/2048 of the longest box side, and the projection octree's refinement limit deepens
  /// until its cells are at most two such sizes (depth 15 at most: 1/32768 of the box). Set by the
  /// automatic local sizes (cut features, rims thinner than an edge); > 0 when given.
  std::optional<double> smallest_size;
  /// Projection: one size everywhere. By default (false) sizes shrink, graded, where the box or a
  /// region plane cuts f = 0 in a feature smaller than an edge (a cut curve turning within an edge, a
  /// strip or slit narrower than one), and where f = 0 itself turns by more than 0.4 radians within a
  /// quarter edge (a rim or tube thinner than an edge: docs/algorithms.md 4.12), so that no triangle
  /// must span it (MeshStats::local_sizes).
  bool uniform = false;
  /// Projection, without `uniform`: whether the sizes also shrink where the box or a region plane cuts
  /// f = 0 (true by default). A caller that trims the mesh well inside its box (the faces of two solids
  /// intersected, api/curved_cut.hpp) turns it off: refining a cut that is thrown away costs vertices and
  /// the multiresolution refinement.
  bool cut_sizes = true;
  /// Projection: points around which sizes shrink to the edge length / 2^refine_around_depth, graded
  /// at 0.2 per unit distance; ignored with `uniform`. The command line passes the
  /// singular points of f = 0 it found (singular_points.hpp), so the mesh around a cusp or a crossing
  /// of sheets is finer. In the user's coordinates (a frame rotates them with the surface).
  std::vector<Vec3> refine_around;
  int refine_around_depth = 2;  ///< 0..6

  /// \throw SettingError for a bound out of range.
  void validate() const;
};

/// The target edge length, or with max_error / size_field the largest size: edge_length when given,
/// else the longest side of `box` / 64 (/ 16 with max_error or a size_field).
inline double default_edge_length(const SizeSettings& s, const Box& box) {
  return s.edge_length.value_or(box.size().maxCoeff() / (s.max_error || s.size_field ? 16.0 : 64.0));
}

/// `box` itself when it is finite with lo < hi on every axis (the region a mesher may mesh).
/// \throw SettingError naming "box" otherwise.
const Box& valid_box(const Box& box);

/// Target sizes resolved over a region: the one description of sizes that the projection mesher (cell
/// sizes, segments per side) and the clean-up (split and collapse thresholds) both follow.
struct TargetSizes {
  double largest = 0.0;                     ///< the size where nothing asks for less (the edge length)
  double smallest = 0.0;                    ///< the floor of a varying size (near singular points)
  std::optional<double> max_error;          ///< curvature sizes for a chordal error bound
  std::function<double(const Vec3&)> user;  ///< a caller's size field
  /// Whether sizes vary over the surface (max_error or a size field).
  bool varies() const { return max_error.has_value() || static_cast<bool>(user); }
};

/// The sizes `s` asks for over `box`: largest = default_edge_length(s, box); smallest = 1/2048 of the
/// longest box side (at most largest); max_error and size_field as given.
TargetSizes target_sizes(const SizeSettings& s, const Box& box);

/// The deepest octree level a mesh may use.
inline constexpr int kOctreeDepthLimit = 12;

/// The octree of the projection mesher (Sipos & Salvi 2021, sec. 2: a partition of single-sheet cells).
struct OctreeSettings {
  /// Depth limits (the root cell is the box made cubic). Surface cells start at the depth whose cell
  /// size fits the resolution and edge_length, clamped to [min_depth, max_depth]; cells that fail the
  /// single-sheet or acceptance tests are refined up to max_depth. 0 <= min <= max <= 12. With
  /// automatic resolution, when the edge length asks for starting cells at max_depth or deeper, the
  /// limit becomes that depth plus refinement_levels (at most 12), so small features can still be refined.
  int min_depth = 2;
  int max_depth = 8;
  /// With automatic resolution (resolution 0): the starting depth goes one level deeper while more than
  /// half of the patch corners lie in cells longer than this many radii of the largest principal
  /// curvature there (cell size * kappa_max, about the normal turn across the cell in radians), as long
  /// as such cells stay above 3 target edge lengths. One patch then does not wrap around a tube, where
  /// its lattice would be strained (docs/whole-surface-quality.md). 0 disables; otherwise > 0.
  double max_cell_curvature = 1.5;
  /// A cell whose patch is rejected (or whose topology is in doubt) is split, locally, at most this many
  /// levels below the starting depth (and never below max_depth), 0..12; the octree stays 2:1 balanced
  /// and coarse patches take their finer neighbours' crossings as extra (flat) corners. Cells still
  /// failing at that depth are closed by fans over their shared boundaries (reported in the statistics).
  int refinement_levels = 3;

  /// \throw SettingError for a depth or level out of range.
  void validate() const;
};

/// The most segments a patch side may have (the template resolution r).
inline constexpr int kMaxPatchResolution = 64;

/// The patches: their template resolution, barycentric coordinates and base surface.
struct PatchSettings {
  /// Segments per patch side (the template resolution r), 1..64; 0 (default): chosen per depth as the
  /// mean length of the loop sides at that depth over the edge length (with a size field: the cell size
  /// over the local size), at least 1, so the mean edge is about the edge length.
  int resolution = 0;
  /// Generalized barycentric coordinates for the base patch and the projection directions.
  enum class Coordinates { Wachspress, MeanValue } coordinates = Coordinates::Wachspress;
  /// The base surface of each patch, from which interior vertices are projected (docs/algorithms.md 3.5).
  ///   Automatic (default): Barycentric for a partition's cells, Coons for a composite's patches (whose
  ///     curves are known from the construction).
  ///   Barycentric: the paper's eq. (1), sum_k lambda_k Q_k; in a cell, boundary vertices are chord
  ///     points projected in the face plane and directions blend the cell-edge directions at the
  ///     corners; on a composite patch, the corners' combination under the curves' shared samples.
  ///   Coons: the multi-sided C0 Coons patch (Salvi 2020, arXiv:2002.11347) over the face curves (in a
  ///     cell traced as dense polylines, boundary vertices at equal arc length on them, directions
  ///     blending the unit gradients at the corners) or over a composite patch's curves.
  enum class Base { Automatic, Barycentric, Coons } base = Base::Automatic;

  /// \throw SettingError for a resolution out of range.
  void validate() const;
};

/// Projection onto f = 0 and its acceptance tests.
struct ProjectionSettings {
  /// Acceptance: largest angle between a projection ray and grad f at the hit (interior vertices), and
  /// between a boundary ray and the in-face gradient (boundary vertices), in degrees, in (0, 90).
  double max_ray_angle = 75.0;
  double max_boundary_ray_angle = 80.0;
  /// Ray-march steps per traversal of a cell (before the bracketed refinement), 4..4096.
  int march_steps = 32;
  /// Attach the per-vertex attribute "role": 0 patch corner, 1 patch side, 2 patch interior, 3 patch
  /// centre (ring templates), 4 centre of a fallback fan.
  bool vertex_roles = false;

  /// \throw SettingError for an angle or step count out of range.
  void validate() const;
};

/// How marching cubes places a vertex on a crossed grid edge.
enum class EdgeRoot {
  Bracketed,  ///< a bracketed root finder (Illinois / bisection safeguard) to ~1e-13 of the edge: on f = 0
  Linear,     ///< linear interpolation of the two end values, as in the original algorithm
};

/// Marching cubes (Lorensen & Cline 1987), the baseline, and its Laplace fairing.
struct MarchingCubesSettings {
  /// Cells along the longest box axis; cells are cubes and the grid covers the whole box. 1..4096.
  int grid = 64;
  EdgeRoot edge_root = EdgeRoot::Bracketed;
  /// The grid origin is shifted by this fraction of a cell along the non-dyadic direction
  /// (0.1234, 0.5678, 0.9012) so symmetric surfaces do not pass through grid points. In [0, 1).
  double grid_offset = 1e-3;
  /// Rounds of Laplace fairing with re-projection applied to the Marching Cubes mesh (fairing.hpp), 0..10000.
  int fair_iterations = 0;

  /// \throw SettingError for a grid, offset or round count out of range.
  void validate() const;
};

/// Rounds of remeshing applied to projection meshes (and by remesh_on_surface) when
/// CleanupSettings::remesh_iterations is empty: the valence-6 share stops growing after about 6 rounds.
inline constexpr int kDefaultRemeshIterations = 6;
/// The clean-up's default flips per borrowing chain (CleanupSettings::valence_search).
inline constexpr int kDefaultValenceSearch = 30;
/// The clean-up's default exactness sweeps (CleanupSettings::curvature_sweeps).
inline constexpr int kDefaultCurvatureSweeps = 8;
/// Largest accepted valence_search and curvature_sweeps: bounds on the work a request may ask for.
inline constexpr int kMaxValenceSearch = 10000;
inline constexpr int kMaxCurvatureSweeps = 1000;

/// The whole-surface clean-up (remesh.hpp).
/// Presets of speed against quality (Settings::quality; CLI --quality preview|default|fine).
enum class Quality {
  /// The paper's quick preview: the projection mesh with only a local repair of what its seams and
  /// corners leave (small angles, irregular vertices); as fast as possible with valence 6 >= 90% and
  /// smallest angle >= 20 degrees.
  Preview,
  /// The full clean-up (remesh_iterations, valence_search, curvature_sweeps as set).
  Default,
  /// Default, then more curvature sweeps and relaxation: the lowest curvature error at a vertex count.
  Fine,
};

struct CleanupSettings {
  /// The preset; Default leaves remesh_iterations, valence_search and curvature_sweeps in charge, the
  /// other two override them (docs/performance.md).
  Quality quality = Quality::Default;
  /// Rounds of surface-bound remeshing (split, collapse, flip, relax, project) applied to the output,
  /// 0..100. Empty (default): 6 for projection, 0 for marching cubes. 0 gives the paper's method alone.
  std::optional<int> remesh_iterations;
  /// Flips tried per chain in the final sweep that pulls apart stuck 5-7 vertex pairs, 0..10000; 0
  /// skips it: faster, 1-3 points less valence 6.
  int valence_search = kDefaultValenceSearch;
  /// Sweeps of tangential vertex moves that make the cotangent Laplacian exact for quadratic functions
  /// at every vertex, 0..1000: discrete mean-curvature error 2-3 times lower on 10k-vertex meshes; 0
  /// skips them (faster).
  int curvature_sweeps = kDefaultCurvatureSweeps;
  /// Where the box or a region plane cuts the surface open: whether a cut edge longer than 4/3 of the
  /// target edge is split at a new point of the cut curve (true by default: the cut takes the mesh's
  /// edge, as the interior does). Library only: where the faces of two solids fail to join on cuts split
  /// so, or join with a triangle under 25 degrees (api/curved_cut.hpp), their operands are meshed again
  /// with it off, the cut as the mesher made it.
  bool split_cut = true;

  /// \throw SettingError for a count out of range.
  void validate() const;
};

/// The largest refinement level a run may ask for (RefineSettings::refine).
inline constexpr int kMaxRefineLevel = 16;

/// Multiresolution meshing (docs/algorithms.md 8): a coarse base meshed by the projection mesher and the
/// clean-up at k times the target edge length, every base triangle then cut into k^2 triangles whose
/// new vertices are put on f = 0 and relaxed. Projection only.
struct RefineSettings {
  /// The level k. 0 (default): chosen from the surface's curvature (k = 1 where a coarser base would not
  /// resolve it, up to 8 on gently curved surfaces; 1 with max_error or a size_field, where a graded
  /// base measured worse, and when remesh_iterations is 0, the paper's method alone). 1: no refinement
  /// (the projection mesher and the clean-up at the target size). 2..16: that k (with max_error or a
  /// size_field over a base graded k times coarser), halved where a refined point cannot be put safely
  /// on f = 0. 0..kMaxRefineLevel.
  int refine = 0;

  /// \throw SettingError for a level out of range.
  void validate() const;
};

/// The most worker threads a run may ask for (BudgetSettings::threads).
inline constexpr int kMaxThreads = 1024;

/// The quality preset named "preview", "default" or "fine". \throw SettingError("quality") otherwise.
Quality parse_quality(const std::string& name);
/// "preview", "default" or "fine".
const char* quality_name(Quality quality);

/// Progress of a long run, reported through BudgetSettings::progress.
struct Progress {
  std::size_t done = 0;   ///< work units done (e.g. grid slabs, cells)
  std::size_t total = 0;  ///< work units in all
  /// The stage the units belong to ("partition", "base", "cleanup", "refine", ...); null: the method's
  /// own (grid slabs of marching cubes, partition rounds of the projection mesher).
  const char* stage = nullptr;
};

/// What a run may spend, and how the caller follows and stops it.
struct BudgetSettings {
  /// Abort with LimitError when the output would exceed this many vertices. 0: no limit.
  std::size_t max_vertices = 0;
  /// Abort with LimitError after this many evaluations of f (values, gradients, Hessians and interval
  /// bounds all count). 0: no limit.
  std::uint64_t max_evaluations = 0;
  /// Abort with LimitError once the run has taken this many seconds (checked every 256 evaluations).
  /// 0: no limit. Must be >= 0.
  double time_limit = 0.0;
  /// Called now and then from the meshing thread; may be empty.
  std::function<void(const Progress&)> progress;
  /// When set and true, the mesher stops with LimitError("cancelled") at the next check.
  const std::atomic<bool>* cancel = nullptr;
  /// Worker threads, 1..kMaxThreads; 0 (default): every core. The output is the same bytes for any count.
  int threads = 0;

  /// \throw SettingError for a negative or non-finite time limit, or threads out of range.
  void validate() const;
  /// \throw LimitError("cancelled", "cancel") when cancel is set and true.
  void check_cancel() const;
  /// \throw LimitError naming max_vertices when `vertices` exceeds it.
  void check_vertices(std::size_t vertices) const;
};

}  // namespace isopatch
