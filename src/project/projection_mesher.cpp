// The projection mesher for whole surfaces (see include/isopatch/projection.hpp). Three phases per
// partition, each a loop over independent items, so they can later run in parallel with the same
// output: (1) the boundary vertices of every shared side, (2) every patch, (3) assembly by IDs.
#include <isopatch/curvature.hpp>
#include <isopatch/error.hpp>
#include <isopatch/projection.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "partition/cube.hpp"
#include "partition/cube_cycles.hpp"
#include "partition/partition.hpp"
#include "patch/base_surface.hpp"
#include "patch/coons_patch.hpp"
#include "patch/patch_template.hpp"
#include "project/face_curve.hpp"
#include "project/patch_projection.hpp"
#include "project/ray_march.hpp"
#include "project/side_points.hpp"
#include "surface/sampler.hpp"
#include "surface/target_size.hpp"

namespace isopatch {
namespace {

/// A side shared by two loops: crossing ids from < to, and the face it lies on.
struct Side {
  std::uint32_t from = 0;
  std::uint32_t to = 0;
  FaceId face;
  friend auto operator<=>(const Side& a, const Side& b) {
    return std::tie(a.from, a.to) <=> std::tie(b.from, b.to);
  }
  friend bool operator==(const Side& a, const Side& b) { return a.from == b.from && a.to == b.to; }
};

struct Counters {
  std::map<int, std::size_t> patches_by_sides;
  std::size_t rejected_patches = 0;
  std::map<PatchVerdict, std::size_t> rejected_by_verdict;
  std::size_t rejected_sides = 0;
  std::size_t fallback_cells = 0;
  std::size_t unprojected_vertices = 0;
  std::size_t refined_patches = 0;  ///< patches of leaves deeper than the starting depth
  PatchStats patch;
};

/// Rounds of local refinement before failing cells are closed by fans.
constexpr int kMaxRounds = 8;

/// Automatic resolution aims at this many segments per side (cells of 4..8 edge lengths).
constexpr double kAutoSegments = 8.0;
/// The deepest octree level a mesh may use (Settings::max_depth).
constexpr int kDepthLimit = 12;

void check_settings(const Settings& s) {
  if (s.edge_length && !(std::isfinite(*s.edge_length) && *s.edge_length > 0.0))
    throw InputError("edge length must be a positive number");
  if (s.resolution != 0 &&
      (s.resolution < PatchTemplate::kMinResolution || s.resolution > PatchTemplate::kMaxResolution))
    throw InputError("resolution must be 0 (automatic) or between 1 and 64, got " +
                     std::to_string(s.resolution));
  if (s.min_depth < 0 || s.max_depth > kDepthLimit || s.min_depth > s.max_depth)
    throw InputError("depths must satisfy 0 <= min-depth <= max-depth <= " + std::to_string(kDepthLimit) +
                     ", got " + std::to_string(s.min_depth) + " and " + std::to_string(s.max_depth));
  if (!(s.max_ray_angle > 0.0 && s.max_ray_angle < 90.0) ||
      !(s.max_boundary_ray_angle > 0.0 && s.max_boundary_ray_angle < 90.0))
    throw InputError("acceptance angles must lie strictly between 0 and 90 degrees");
  if (s.march_steps < 4 || s.march_steps > 4096) throw InputError("march steps must be between 4 and 4096");
  if (!(std::isfinite(s.max_cell_curvature) && s.max_cell_curvature >= 0.0))
    throw InputError("the largest cell curvature must be a finite number >= 0 (0: off)");
  if (s.refinement_levels < 0 || s.refinement_levels > 12)
    throw InputError("refinement levels must be between 0 and 12");
}

ProjectionParams projection_params(const Settings& s, int resolution) {
  const double to_radians = std::numbers::pi / 180.0;
  ProjectionParams p;
  p.resolution = resolution;
  p.march_steps = s.march_steps;
  p.cos_max_ray_angle = std::cos(s.max_ray_angle * to_radians);
  p.cos_max_boundary_angle = std::cos(s.max_boundary_ray_angle * to_radians);
  return p;
}

double target_edge(const Box& box, const Settings& s) {
  return default_edge_length(s, box);
}

/// With a fixed resolution r: the depth whose cells are closest (in log scale) to r * edge length.
/// With automatic resolution: the coarsest depth whose cells are at most kAutoSegments edges long.
/// Not clamped.
double depth_for_edge(const Lattice& lattice, const Box& box, const Settings& s) {
  const double edge = target_edge(box, s);
  return s.resolution > 0 ? std::round(std::log2(lattice.size / (edge * s.resolution)))
                          : std::ceil(std::log2(lattice.size / (edge * kAutoSegments)) - 1e-9);
}

/// The refinement limit: max_depth, raised with automatic resolution when the edge length asks for
/// starting cells at or below it to that depth plus refinement_levels (at most kDepthLimit). Otherwise an
/// edge length far below the finest cells leaves features of a few cells (a sphere of radius 0.01 in a
/// box of side 2 at depth 8) no room to refine, and the fans that close the rejected patches fold over.
/// A fixed resolution keeps max_depth (single-cell meshes set both depths to 0).
int depth_limit(const Lattice& lattice, const Box& box, const Settings& s) {
  if (s.resolution != 0) return s.max_depth;
  const double wanted = depth_for_edge(lattice, box, s);
  if (!(wanted >= s.max_depth)) return s.max_depth;
  return static_cast<int>(std::min<double>(kDepthLimit, wanted + s.refinement_levels));
}

int initial_depth(const Lattice& lattice, const Box& box, const Settings& s, int max_depth) {
  return static_cast<int>(std::clamp(depth_for_edge(lattice, box, s), static_cast<double>(s.min_depth),
                                     static_cast<double>(max_depth)));
}

CoordinateKind coordinate_kind(const Settings& s) {
  return s.coordinates == Settings::Coordinates::MeanValue ? CoordinateKind::MeanValue
                                                           : CoordinateKind::Wachspress;
}

/// Leaves whose topology is in doubt (two loops, an ambiguous face, an edge crossed twice, no loop):
/// only a finer partition helps. The other single-sheet tests (face, normal cone) are sufficient
/// conditions; a leaf failing only those still gets its patch, and the acceptance tests decide.
bool needs_refinement(const Leaf& leaf) {
  if (leaf.loops.size() != 1) return true;
  switch (leaf.reason) {
    case ComplexReason::None:
    case ComplexReason::FaceTest:
    case ComplexReason::NormalCone:
      return false;
    case ComplexReason::SeveralLoops:
    case ComplexReason::AmbiguousFace:
    case ComplexReason::EdgeTest:
    case ComplexReason::Orientation:
      return true;
  }
  return true;
}

/// An edge crossed twice in a few cells is mostly an edge grazing the surface, which the fans close
/// correctly; in more than this share of the leaves, sheets closer than a cell are the likelier cause.
constexpr double kDoubtfulEdgeShare = 0.01;

/// A face whose every sample (corners and centre) lies within this share of the cell side of f = 0,
/// with grad f within acos(kGrazingNormal) of the face normal, holds the surface nearly in its plane.
constexpr double kGrazingDistance = 0.05;
constexpr double kGrazingNormal = 0.9;

/// Whether the leaf has an ambiguous face (cube_cycles.hpp face_ambiguous, from its corner signs) and
/// f = 0 only grazes every such face: it lies nearly in the face's plane (a point where its tangent
/// plane is the face). Such a face stays ambiguous at every depth, since finer faces lie in the same
/// plane, yet it holds one sheet whose cut is decided within kGrazingDistance of the cell: not two
/// sheets closer than the cell. Sheets that close have a sign change of f between them, where grad f
/// turns, and fail the normal condition. Evaluates f and grad f at the corners and centre of the
/// ambiguous faces only.
bool only_grazing_ambiguous_faces(const Sampler& f, const Leaf& leaf) {
  const double side = leaf.box.size().maxCoeff();
  bool ambiguous = false;
  for (int face = 0; face < 6; ++face) {
    if (!face_ambiguous(leaf.config, face)) continue;
    ambiguous = true;
    const auto axis = static_cast<std::size_t>(cube::kFaceAxis[static_cast<std::size_t>(face)]);
    const auto grazes = [&](const Vec3& p) {
      const ValueGradient vg = f.value_gradient(p);
      const double g = vg.gradient.norm();
      return g > 0.0 && std::abs(vg.value) <= kGrazingDistance * side * g &&
             std::abs(vg.gradient[static_cast<Eigen::Index>(axis)]) >= kGrazingNormal * g;
    };
    Vec3 centre = Vec3::Zero();
    for (const int corner : cube::kFace[static_cast<std::size_t>(face)]) {
      const auto& offset = cube::kCorner[static_cast<std::size_t>(corner)];
      const Vec3 p = leaf.box.lo + Vec3(offset[0], offset[1], offset[2]).cwiseProduct(leaf.box.size());
      if (!grazes(p)) return false;
      centre += 0.25 * p;
    }
    if (!grazes(centre)) return false;
  }
  return ambiguous;
}

struct DoubtfulLeaves {
  std::size_t count = 0;
  double largest_side = 0.0;  ///< of the largest doubtful leaf (0 without any)
  std::array<std::size_t, kComplexReasonCount> by_reason{};
  /// Doubtful leaves that put the topology in question: two loops or an ambiguous face always, edges
  /// crossed twice when they are more than kDoubtfulEdgeShare of the leaves; not the ambiguous faces
  /// that the surface grazes (grazing_faces).
  std::size_t topology = 0;
  /// Leaves whose ambiguous faces the surface only grazes (only_grazing_ambiguous_faces).
  std::size_t grazing_faces = 0;
};

/// The leaves still in doubt (needs_refinement) after the partition has split them to its depth limit.
DoubtfulLeaves leaves_needing_refinement(const Partition& partition, const Sampler& f) {
  DoubtfulLeaves doubtful;
  for (const Leaf& leaf : partition.leaves)
    if (needs_refinement(leaf)) {
      ++doubtful.count;
      ++doubtful.by_reason[static_cast<std::size_t>(leaf.reason)];
      doubtful.largest_side = std::max(doubtful.largest_side, leaf.box.size().maxCoeff());
      if (leaf.reason == ComplexReason::AmbiguousFace && only_grazing_ambiguous_faces(f, leaf))
        ++doubtful.grazing_faces;
    }
  const auto reason = [&](ComplexReason r) { return doubtful.by_reason[static_cast<std::size_t>(r)]; };
  doubtful.topology =
      reason(ComplexReason::SeveralLoops) + reason(ComplexReason::AmbiguousFace) - doubtful.grazing_faces;
  if (static_cast<double>(reason(ComplexReason::EdgeTest)) >
      kDoubtfulEdgeShare * static_cast<double>(partition.leaves.size()))
    doubtful.topology += reason(ComplexReason::EdgeTest);
  return doubtful;
}

/// The target edge length at a point (target_size.hpp): constant unless max_error or a size_field is set.
std::function<double(const Vec3&)> size_function(const Surface& surface, const SizeSpec& spec) {
  if (!spec.varies()) return [edge = spec.largest](const Vec3&) { return edge; };
  return [&surface, spec](const Vec3& p) { return target_size(surface, spec, p); };
}

/// Surface leaves shallower than `max_depth` whose cell is longer than kAutoSegments times the
/// smallest target size at their corners.
std::vector<CellKey> leaves_too_large_for(const Partition& partition,
                                          const std::function<double(const Vec3&)>& size_at, int max_depth) {
  std::vector<CellKey> keys;
  for (const Leaf& leaf : partition.leaves) {
    if (leaf.depth >= max_depth) continue;
    double h = std::numeric_limits<double>::infinity();
    for (const Loop& loop : leaf.loops)
      for (std::uint32_t c : loop.corners) h = std::min(h, size_at(partition.crossings[c].position));
    if (leaf.box.size().maxCoeff() > kAutoSegments * h) keys.push_back(CellKey{leaf.depth, leaf.coords});
  }
  return keys;
}

/// A cell must stay at least this many target edge lengths long to be split for its curvature.
constexpr double kMinCurvedCellEdges = 3.0;

/// Whether the surface is curved at the scale of the starting cells (Settings::max_cell_curvature):
/// more than half of the corners of the starting-depth leaves sit in a cell longer than `max_turn`
/// radii of the largest principal curvature at the corner and longer than kMinCurvedCellEdges target
/// sizes. A median, not a per-leaf rule: splitting single leaves adds depth transitions, whose seams
/// cost more than the strain they remove (measured in docs/whole-surface-quality.md).
bool starting_cells_too_curved(const Partition& partition, const Surface& surface, int depth, double max_turn,
                               const std::function<double(const Vec3&)>& size_at) {
  // A crossing is a corner of up to four leaves: its curvature and size are evaluated once (-1: not yet).
  std::vector<double> kappa(partition.crossings.size(), -1.0), h(partition.crossings.size(), -1.0);
  std::size_t curved = 0, corners = 0;
  for (const Leaf& leaf : partition.leaves) {
    if (leaf.depth != depth) continue;
    const double size = leaf.box.size().maxCoeff();
    for (const Loop& loop : leaf.loops)
      for (std::uint32_t c : loop.corners) {
        const Vec3& p = partition.crossings[c].position;
        if (kappa[c] < 0.0) kappa[c] = max_abs_principal_curvature(surface, p), h[c] = size_at(p);
        ++corners;
        // Infinite curvature (a singular point) counts as curved; NaN compares false.
        if (size * kappa[c] > max_turn && size > kMinCurvedCellEdges * h[c]) ++curved;
      }
  }
  return 2 * curved > corners;
}

void check_cancel(const Settings& s) {
  if (s.cancel && s.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled");
}

void check_vertex_budget(const Settings& s, std::size_t vertices) {
  if (s.max_vertices > 0 && vertices > s.max_vertices)
    throw LimitError("the mesh would exceed --max-vertices " + std::to_string(s.max_vertices));
}

/// Meshes one partition. A leaf whose patch or one of whose sides is rejected is listed in to_split()
/// when it is shallower than `refinable_depth` (the caller then refines it and meshes again); deeper
/// rejected leaves, and leaves whose topology is still in doubt, are closed by fans over their shared
/// boundaries.
class PartitionMesher {
 public:
  /// `resolution` > 0: every side gets that many segments; 0: each side gets its own count from the
  /// leaves that share it and the target size at their corners (`size_at`; `uniform_sizes` when it is
  /// constant, see side_factor).
  PartitionMesher(const Sampler& f, const Partition& partition, const Settings& settings, int resolution,
                  int refinable_depth, std::function<double(const Vec3&)> size_at, bool uniform_sizes)
      : f_(f),
        part_(partition),
        settings_(settings),
        params_(projection_params(settings, std::max(resolution, 1))),
        fixed_resolution_(resolution),
        refinable_depth_(refinable_depth),
        size_at_(std::move(size_at)),
        uniform_sizes_(uniform_sizes) {}

  /// The mesh; meaningful only when to_split() is empty afterwards.
  Mesh run(Counters& counters) {
    collect_sides();
    compute_sides(counters);
    for (std::size_t l = 0; l < part_.leaves.size(); ++l) {
      check_cancel(settings_);
      if (settings_.progress && l % 64 == 0) settings_.progress(Progress{l, part_.leaves.size()});
      mesh_leaf(l, counters);
      check_vertex_budget(settings_, mesh_.positions.size());
    }
    if (settings_.vertex_roles) mesh_.set_attribute("role", std::move(roles_));
    return std::move(mesh_);
  }

  /// Smallest and largest segment count over the sides (0, 0 without sides).
  std::pair<int, int> segment_range() const {
    if (side_segments_.empty()) return {0, 0};
    const auto [lo, hi] = std::minmax_element(side_segments_.begin(), side_segments_.end());
    return {*lo, *hi};
  }

  /// Leaves to split before meshing again, sorted and unique.
  std::vector<CellKey> to_split() const {
    std::vector<CellKey> keys;
    for (std::size_t l : split_leaves_)
      keys.push_back(CellKey{part_.leaves[l].depth, part_.leaves[l].coords});
    return keys;
  }

 private:
  /// Segments of side s (shared by both its patches).
  int segments(std::size_t s) const { return side_segments_[s]; }

  /// Segments per side for a leaf: the fixed resolution, or its cell size times side_factor(depth) over
  /// the smallest target size at its corners (at least 1), so leaves of one depth share one template
  /// resolution and deeper leaves get proportionally fewer segments.
  int leaf_resolution(std::size_t l) {
    if (fixed_resolution_ > 0) return fixed_resolution_;
    const Leaf& leaf = part_.leaves[l];
    double h = std::numeric_limits<double>::infinity();
    for (const Loop& loop : leaf.loops)
      for (std::uint32_t c : loop.corners) h = std::min(h, crossing_size(c));
    const double cell = part_.lattice.unit() * part_.lattice.step(leaf.depth);
    // The side factor never takes a leaf down to one segment per side (a patch of corners only, whose
    // fans leave most vertices irregular) where the cell size alone gives two or more.
    const double r =
        std::max(std::round(cell * side_factor(leaf.depth) / h), std::min(2.0, std::round(cell / h)));
    return static_cast<int>(std::clamp(r, 1.0, static_cast<double>(PatchTemplate::kMaxResolution)));
  }

  /// The segment count of side i: the smallest resolution of the leaves that share it, so the finer
  /// neighbour keeps its regular template and the coarser one merges boundary vertices.
  int side_segments(std::size_t i) {
    if (leaf_resolutions_.empty()) leaf_resolutions_.assign(part_.leaves.size(), 0);
    int k = PatchTemplate::kMaxResolution;
    for (std::size_t l : side_leaves_[i]) {
      if (leaf_resolutions_[l] == 0) leaf_resolutions_[l] = leaf_resolution(l);
      k = std::min(k, leaf_resolutions_[l]);
    }
    return k;
  }

  /// With uniform sizes: the mean length of the loop sides (corner to corner) of the leaves at `depth`
  /// over their cell size, so that r = cell * factor / h gives edges of about h. A plane cuts a cube in
  /// sides shorter than the cell (mean factor 0.7-0.8 on the public surfaces), and counts from the
  /// cell alone gave mean edges of 0.66-0.97 h. 1 with a size field: there the margin of the error
  /// bound (centroid distances 0.3-0.6 of it) comes from the shorter edges and is kept.
  double side_factor(int depth) {
    if (!uniform_sizes_) return 1.0;
    if (side_factors_.empty()) side_factors_.assign(static_cast<std::size_t>(Lattice::kMaxDepth) + 1, 0.0);
    double& factor = side_factors_[static_cast<std::size_t>(depth)];
    if (factor > 0.0) return factor;
    double sum = 0.0;
    std::size_t count = 0;
    for (const Leaf& leaf : part_.leaves) {
      if (leaf.depth != depth) continue;
      const double cell = part_.lattice.unit() * part_.lattice.step(leaf.depth);
      for (const Loop& loop : leaf.loops)
        for (std::size_t k = 0; k < loop.corners.size(); ++k) {
          const Vec3& a = part_.crossings[loop.corners[k]].position;
          const Vec3& b = part_.crossings[loop.corners[(k + 1) % loop.corners.size()]].position;
          sum += (a - b).norm() / cell;
          ++count;
        }
    }
    factor = count > 0 && sum > 0.0 ? sum / static_cast<double>(count) : 1.0;
    return factor;
  }

  double crossing_size(std::uint32_t c) {
    if (crossing_sizes_.empty()) crossing_sizes_.assign(part_.crossings.size(), -1.0);
    if (crossing_sizes_[c] < 0.0) crossing_sizes_[c] = size_at_(part_.crossings[c].position);
    return crossing_sizes_[c];
  }

  void collect_sides() {
    std::vector<std::pair<Side, std::size_t>> uses;  // side, leaf using it
    for (std::size_t l = 0; l < part_.leaves.size(); ++l)
      for (const Loop& loop : part_.leaves[l].loops)
        for (std::size_t k = 0; k < loop.corners.size(); ++k) {
          const std::uint32_t a = loop.corners[k];
          const std::uint32_t b = loop.corners[(k + 1) % loop.corners.size()];
          uses.emplace_back(Side{std::min(a, b), std::max(a, b), loop.side_faces[k]}, l);
        }
    std::sort(uses.begin(), uses.end(), [](const auto& x, const auto& y) {
      return x.first < y.first || (x.first == y.first && x.second < y.second);
    });
    for (const auto& [side, leaf] : uses) {
      if (sides_.empty() || !(sides_.back() == side)) {
        sides_.push_back(side);
        side_leaves_.emplace_back();
      }
      side_leaves_.back().push_back(leaf);
    }
  }

  bool refinable(std::size_t leaf) const { return part_.leaves[leaf].depth < refinable_depth_; }

  std::size_t side_index(std::uint32_t a, std::uint32_t b) const {
    const Side key{std::min(a, b), std::max(a, b), FaceId{}};
    const auto it = std::lower_bound(sides_.begin(), sides_.end(), key);
    if (it == sides_.end() || !(*it == key))
      throw Error(ErrorKind::Internal, "projection: a loop side has no record");
    return static_cast<std::size_t>(it - sides_.begin());
  }

  /// Phase 1: boundary vertices of every side; vertex ids: crossings first, then sides in key order.
  void compute_sides(Counters& counters) {
    for (const Crossing& c : part_.crossings) mesh_.positions.push_back(c.position);
    roles_.assign(part_.crossings.size(), 0.0f);
    gradients_.reserve(part_.crossings.size());
    for (const Crossing& c : part_.crossings) gradients_.push_back(c.gradient);
    side_points_.reserve(sides_.size());
    side_accepted_.reserve(sides_.size());
    side_offsets_.reserve(sides_.size());
    for (std::size_t i = 0; i < sides_.size(); ++i) {
      check_cancel(settings_);
      side_segments_.push_back(side_segments(i));
      side_offsets_.push_back(mesh_.positions.size());
      SidePoints s = sample(sides_[i], side_segments_.back());
      if (!s.accepted) {
        ++counters.rejected_sides;
        for (std::size_t leaf : side_leaves_[i])
          if (refinable(leaf)) split_leaves_.insert(leaf);
      }
      side_accepted_.push_back(s.accepted);
      for (const SurfacePoint& p : s.points) {
        mesh_.positions.push_back(p.position);
        gradients_.push_back(p.gradient);
        roles_.push_back(1.0f);
      }
      side_points_.push_back(std::move(s.points));
      check_vertex_budget(settings_, mesh_.positions.size());
    }
  }

  /// The side's inner boundary vertices; with the Coons base also its face curve, kept for the patches.
  SidePoints sample(const Side& side, int segments) {
    const Crossing& from = part_.crossings[side.from];
    const Crossing& to = part_.crossings[side.to];
    ProjectionParams params = params_;
    params.resolution = segments;
    if (settings_.base == Settings::Base::Barycentric)
      return sample_side(f_, part_.lattice, from, to, side.face, params);
    FaceCurve curve = trace_face_curve(f_, part_.lattice, from, to, side.face, params);
    side_curves_.push_back(std::move(curve.dense));
    return SidePoints{std::move(curve.points), curve.accepted};
  }

  /// The base surface of a loop, and the corner directions to blend (method.md 7.1, 7.2, 8.1).
  std::unique_ptr<BaseSurface> base_surface(const Loop& loop, std::vector<Vec3>& directions) const {
    directions.clear();
    if (settings_.base == Settings::Base::Barycentric) {
      std::vector<Vec3> q;
      for (std::uint32_t c : loop.corners) {
        q.push_back(part_.crossings[c].position);
        directions.push_back(part_.crossings[c].direction);
      }
      return std::make_unique<BarycentricBase>(std::move(q));
    }
    std::vector<PolylineCurve> curves;
    for (std::size_t k = 0; k < loop.corners.size(); ++k) {
      const std::uint32_t a = loop.corners[k];
      const std::uint32_t b = loop.corners[(k + 1) % loop.corners.size()];
      std::vector<Vec3> dense = side_curves_[side_index(a, b)];  // stored from the smaller crossing id
      if (a > b) std::reverse(dense.begin(), dense.end());
      curves.emplace_back(std::move(dense));
      directions.push_back(part_.crossings[a].gradient.normalized());
    }
    return std::make_unique<CoonsPatch>(std::move(curves));
  }

  /// Global id of point i (0..k, counted from corner a; 0 and k are the corners) of the side from
  /// crossing a to b with k segments.
  std::uint32_t side_vertex(std::uint32_t a, std::uint32_t b, int i) const {
    const std::size_t s = side_index(a, b);
    const int k = segments(s);
    if (i <= 0) return a;
    if (i >= k) return b;
    const std::size_t j = a < b ? static_cast<std::size_t>(i) : static_cast<std::size_t>(k - i);
    return static_cast<std::uint32_t>(side_offsets_[s] + (j - 1));
  }

  bool loop_sides_accepted(const Loop& loop) const {
    for (std::size_t k = 0; k < loop.corners.size(); ++k)
      if (!side_accepted_[side_index(loop.corners[k], loop.corners[(k + 1) % loop.corners.size()])])
        return false;
    return true;
  }

  /// Phase 2 for one leaf: a projected patch; when it fails, a request to split the leaf or, where it
  /// cannot be split, fans.
  void mesh_leaf(std::size_t l, Counters& counters) {
    if (split_leaves_.contains(l)) return;  // a side failed: the leaf is refined anyway
    const Leaf& leaf = part_.leaves[l];
    const bool simple = !needs_refinement(leaf) && leaf.loops.front().corners.size() >= 3 &&
                        leaf.loops.front().corners.size() <= 12;
    if (simple && loop_sides_accepted(leaf.loops.front())) {
      const PatchVerdict verdict = mesh_patch(leaf, leaf.loops.front(), counters.patch);
      if (verdict == PatchVerdict::Accepted) {
        ++counters.patches_by_sides[static_cast<int>(leaf.loops.front().corners.size())];
        if (leaf.depth > part_.surface_depth) ++counters.refined_patches;
        return;
      }
      ++counters.rejected_patches;
      ++counters.rejected_by_verdict[verdict];
    }
    if (refinable(l)) {
      split_leaves_.insert(l);
      return;
    }
    ++counters.fallback_cells;
    for (const Loop& loop : leaf.loops) mesh_fan(leaf, loop, counters);
  }

  PatchVerdict mesh_patch(const Leaf& leaf, const Loop& loop, PatchStats& patch_stats) {
    const int n = static_cast<int>(loop.corners.size());
    // The template has as many segments per side as the loop's longest side count; a side with fewer
    // takes, for template vertex i, its point round(i k / r): coinciding template vertices merge and the
    // triangles between them vanish (method.md 15, option 1).
    int r = 1;
    for (std::size_t k = 0; k < loop.corners.size(); ++k)
      r = std::max(r, segments(side_index(loop.corners[k], loop.corners[(k + 1) % loop.corners.size()])));
    const auto patch = patch_template(n, r, coordinate_kind(settings_));
    std::vector<Vec3> d;
    const std::unique_ptr<BaseSurface> base = base_surface(loop, d);
    std::vector<std::uint32_t> ids(patch->vertex_count(), 0);
    std::vector<SurfacePoint> points(patch->vertex_count());
    for (std::size_t v = 0; v < patch->vertex_count(); ++v) {
      const VertexTag& tag = patch->tag(static_cast<int>(v));
      if (tag.kind == VertexTag::Kind::Interior) continue;
      const auto k = static_cast<std::size_t>(tag.side);
      const std::uint32_t a = loop.corners[k];
      const std::uint32_t b = loop.corners[(k + 1) % loop.corners.size()];
      if (tag.kind == VertexTag::Kind::Corner) {
        ids[v] = a;
      } else {
        const int count = segments(side_index(a, b));
        ids[v] = side_vertex(a, b, (2 * tag.index * count + r) / (2 * r));
      }
      points[v] = {mesh_.positions[ids[v]], gradients_[ids[v]]};
    }
    const PatchVerdict verdict = project_patch(f_, *patch, *base, d, leaf.box, params_, points, patch_stats);
    if (verdict != PatchVerdict::Accepted) return verdict;
    for (std::size_t v = 0; v < patch->vertex_count(); ++v) {
      if (patch->tag(static_cast<int>(v)).kind != VertexTag::Kind::Interior) continue;
      ids[v] = static_cast<std::uint32_t>(mesh_.positions.size());
      mesh_.positions.push_back(points[v].position);
      gradients_.push_back(points[v].gradient);
      roles_.push_back(static_cast<int>(v) == patch->centre() ? 3.0f : 2.0f);
    }
    for (const TemplateTriangle& t : patch->triangles()) {
      const Triangle tri{ids[static_cast<std::size_t>(t[0])], ids[static_cast<std::size_t>(t[1])],
                         ids[static_cast<std::size_t>(t[2])]};
      if (tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0]) mesh_.triangles.push_back(tri);
    }
    return PatchVerdict::Accepted;
  }

  /// Fallback: the loop's boundary polygon (corners and shared side vertices) fanned around a centre
  /// vertex moved onto f = 0 along the polygon's normal when a ray finds the surface in the cell.
  void mesh_fan(const Leaf& leaf, const Loop& loop, Counters& counters) {
    std::vector<std::uint32_t> polygon;
    for (std::size_t k = 0; k < loop.corners.size(); ++k) {
      const std::uint32_t a = loop.corners[k];
      const std::uint32_t b = loop.corners[(k + 1) % loop.corners.size()];
      polygon.push_back(a);
      for (int i = 1; i < segments(side_index(a, b)); ++i) polygon.push_back(side_vertex(a, b, i));
    }
    Vec3 centre = Vec3::Zero();
    Vec3 normal = Vec3::Zero();
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const Vec3& p = mesh_.positions[polygon[k]];
      const Vec3& q = mesh_.positions[polygon[(k + 1) % polygon.size()]];
      centre += p;
      normal += p.cross(q);
    }
    centre /= static_cast<double>(polygon.size());
    // The centre moves onto f = 0 along the polygon's normal, else along grad f, within the cell grown
    // by half its size (a fallback cell is a poor fit by definition; its fan must still close it).
    RayMarchSettings march;
    march.steps = params_.march_steps;
    const Box& clip = part_.lattice.clip;
    const Box region{(leaf.box.lo - 0.5 * leaf.box.size()).cwiseMax(clip.lo),
                     (leaf.box.hi + 0.5 * leaf.box.size()).cwiseMin(clip.hi)};
    const double f_centre = f_.value(centre);
    std::optional<RayHit> hit;
    if (normal.norm() > 0.0) hit = march_to_surface(f_, centre, f_centre, normal, region, march);
    if (!hit) hit = march_to_surface(f_, centre, f_centre, f_.value_gradient(centre).gradient, region, march);
    Vec3 position = centre;
    Vec3 gradient = normal;
    if (hit) {
      position = hit->point;
      gradient = f_.value_gradient(position).gradient;
    } else {
      ++counters.unprojected_vertices;
    }
    const auto c = static_cast<std::uint32_t>(mesh_.positions.size());
    mesh_.positions.push_back(position);
    gradients_.push_back(gradient);
    roles_.push_back(4.0f);
    for (std::size_t k = 0; k < polygon.size(); ++k)
      mesh_.triangles.push_back({c, polygon[k], polygon[(k + 1) % polygon.size()]});
  }

  const Sampler& f_;
  const Partition& part_;
  const Settings& settings_;
  ProjectionParams params_;
  int fixed_resolution_;
  int refinable_depth_;
  std::function<double(const Vec3&)> size_at_;
  std::vector<double> crossing_sizes_;     // target size at each crossing, -1 until asked
  std::vector<int> leaf_resolutions_;      // per leaf, 0 until asked
  bool uniform_sizes_;                     // size_at_ is constant (see side_factor)
  std::vector<double> side_factors_;       // per depth, 0 until asked (see side_factor)
  std::vector<int> side_segments_;         // per side, in key order
  std::vector<std::size_t> side_offsets_;  // per side, the mesh id of its first inner point
  std::vector<Side> sides_;
  std::vector<std::vector<std::size_t>> side_leaves_;  // per side, the leaves whose loops use it
  std::set<std::size_t> split_leaves_;
  std::vector<std::vector<SurfacePoint>> side_points_;
  std::vector<std::vector<Vec3>> side_curves_;  // Coons base: dense face curve per side, in key order
  std::vector<bool> side_accepted_;
  std::vector<Vec3> gradients_;  // per mesh vertex
  std::vector<float> roles_;     // per mesh vertex, see Settings::vertex_roles
  Mesh mesh_;
};

}  // namespace

Mesh mesh_projection(const Surface& surface, const Settings& settings, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  check_settings(settings);
  const Box box = settings.box.value_or(surface.box());
  if (!box.valid()) throw InputError("the box must have lo < hi on every axis");
  const Sampler f(surface);
  Counters counters;
  std::uint64_t partition_values = 0, partition_gradients = 0;
  std::size_t refinements = 0, curvature_depth_steps = 0;
  bool depth_settled = false;
  const Lattice root = make_lattice(box, 0);
  PartitionSettings ps;
  ps.adaptive = true;
  ps.cancel = settings.cancel;
  const int max_depth = depth_limit(root, box, settings);
  ps.surface_depth = initial_depth(root, box, settings, max_depth);
  const SizeSpec sizes = size_spec(settings, box);
  const std::function<double(const Vec3&)> size_at = size_function(surface, sizes);
  for (int round = 0;; ++round) {
    check_cancel(settings);
    // Cells whose topology is in doubt (two sheets, an ambiguous face) are split by the partition down to
    // max_depth: a coarser fan there would give a closed mesh of the wrong topology. Rejected patches
    // are refined at most refinement_levels below the starting depth (a size field: down to max_depth).
    ps.max_depth = std::max(max_depth, ps.surface_depth);
    const int patch_depth = std::max(
        ps.surface_depth,
        sizes.varies() ? max_depth : std::min(max_depth, ps.surface_depth + settings.refinement_levels));
    const Partition partition = build_partition(surface, box, ps);
    partition_values += partition.stats.value_evaluations;
    partition_gradients += partition.stats.gradient_evaluations;
    if (settings.progress)
      settings.progress(Progress{static_cast<std::size_t>(round), static_cast<std::size_t>(kMaxRounds)});
    if (partition.leaves.empty()) {
      // Nothing found yet: look finer (cheap where intervals or the heuristic prune), down to max_depth.
      if (ps.surface_depth >= max_depth)
        throw NoSurfaceError("no surface in the box: f = 0 crosses no cell down to depth " +
                             std::to_string(ps.surface_depth));
      ++ps.surface_depth;
      ps.force_split.clear();
      continue;
    }
    // With automatic resolution, patches should not wrap around the surface's tubes: while most of the
    // starting cells are too curved, start one level deeper (once per depth, before any local split).
    if (!depth_settled) {
      depth_settled = settings.resolution != 0 || settings.max_cell_curvature == 0.0 ||
                      ps.surface_depth >= max_depth ||
                      !starting_cells_too_curved(partition, surface, ps.surface_depth,
                                                 settings.max_cell_curvature, size_at);
      if (!depth_settled) {
        ++ps.surface_depth;
        ++curvature_depth_steps;
        ps.force_split.clear();
        --round;  // a new starting depth, not a refinement round
        continue;
      }
    }
    // Sides get their own segment counts unless the resolution is fixed.
    const int resolution = settings.resolution;
    if (sizes.varies() && round < kMaxRounds) {
      // The size field asks for cells of at most kAutoSegments local edge lengths.
      std::vector<CellKey> split = leaves_too_large_for(partition, size_at, patch_depth);
      if (!split.empty()) {
        ps.force_split.insert(ps.force_split.end(), split.begin(), split.end());
        ++refinements;
        continue;
      }
    }
    // After kMaxRounds rounds of refinement, whatever still fails is closed by fans.
    const int refinable_depth = round < kMaxRounds ? patch_depth : 0;
    PartitionMesher mesher(f, partition, settings, resolution, refinable_depth, size_at, !sizes.varies());
    // Per-round counters start afresh; rejections add up over the rounds.
    counters.patches_by_sides.clear();
    counters.fallback_cells = counters.unprojected_vertices = counters.refined_patches = 0;
    counters.patch = PatchStats{};
    std::optional<Mesh> mesh = mesher.run(counters);
    if (const std::vector<CellKey> split = mesher.to_split(); !split.empty()) {
      ps.force_split.insert(ps.force_split.end(), split.begin(), split.end());
      ++refinements;
      continue;
    }
    const int depth = ps.surface_depth;
    const DoubtfulLeaves doubtful = leaves_needing_refinement(partition, f);
    mesh->triangles.shrink_to_fit();
    if (stats) {
      stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      stats->value_evaluations = partition_values + f.value_count();
      stats->gradient_evaluations = partition_gradients + f.gradient_count();
      stats->vertices = mesh->vertex_count();
      stats->triangles = mesh->triangle_count();
      stats->extra["depth"] = depth;
      stats->extra["resolution"] = resolution;
      stats->extra["side_segments_min"] = mesher.segment_range().first;
      stats->extra["side_segments_max"] = mesher.segment_range().second;
      for (const auto& [n, count] : counters.patches_by_sides)
        stats->extra["patches_" + std::to_string(n)] = static_cast<double>(count);
      stats->extra["rejected_patches"] = static_cast<double>(counters.rejected_patches);
      stats->extra["rejected_sides"] = static_cast<double>(counters.rejected_sides);
      stats->extra["doubtful_cells"] = static_cast<double>(doubtful.count);
      stats->extra["doubtful_cell_size"] = doubtful.largest_side;
      stats->extra["doubtful_topology_cells"] = static_cast<double>(doubtful.topology);
      stats->extra["doubtful_grazing_faces"] = static_cast<double>(doubtful.grazing_faces);
      for (int r = 0; r < kComplexReasonCount; ++r)
        if (const std::size_t n = doubtful.by_reason[static_cast<std::size_t>(r)]; n > 0)
          stats->extra[std::string("doubtful_") + to_string(static_cast<ComplexReason>(r))] =
              static_cast<double>(n);
      stats->extra["max_depth"] = ps.max_depth;
      stats->extra["refined_patches"] = static_cast<double>(counters.refined_patches);
      stats->extra["flat_corner_leaves"] = static_cast<double>(partition.stats.leaves_with_flat_corners);
      for (int d = 0; d <= Lattice::kMaxDepth; ++d)
        if (partition.stats.leaves_per_depth[static_cast<std::size_t>(d)] > 0)
          stats->extra["leaves_depth_" + std::to_string(d)] =
              static_cast<double>(partition.stats.leaves_per_depth[static_cast<std::size_t>(d)]);
      stats->extra["refinements"] = static_cast<double>(refinements);
      stats->extra["curvature_depth_steps"] = static_cast<double>(curvature_depth_steps);
      stats->extra["fallback_cells"] = static_cast<double>(counters.fallback_cells);
      stats->extra["unprojected"] = static_cast<double>(counters.unprojected_vertices);
      stats->extra["gradient_rays"] = static_cast<double>(counters.patch.gradient_rays);
      stats->extra["clamped_base_points"] = static_cast<double>(counters.patch.clamped_base_points);
      stats->extra["base_coons"] = settings.base == Settings::Base::Coons ? 1.0 : 0.0;
    }
    return std::move(*mesh);
  }
}

}  // namespace isopatch
