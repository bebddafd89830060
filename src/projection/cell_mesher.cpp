// One pass of the projection mesher over one partition (cell_mesher.hpp).
#include "projection/cell_mesher.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <tuple>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/stage_timer.hpp"
#include "core/vertex_role.hpp"
#include "ngon/base_surface.hpp"
#include "ngon/coons_patch.hpp"
#include "ngon/domain.hpp"
#include "ngon/patch_template.hpp"
#include "projection/doubtful_cells.hpp"
#include "projection/face_curve.hpp"
#include "projection/fan_centre.hpp"
#include "projection/ray_march.hpp"
#include "projection/side_points.hpp"

namespace isopatch {
namespace {

CoordinateKind coordinate_kind(const PatchSettings& s) {
  return s.coordinates == PatchSettings::Coordinates::MeanValue ? CoordinateKind::MeanValue
                                                                : CoordinateKind::Wachspress;
}

}  // namespace

void CellMesherCounters::start_pass() {
  patches_by_sides.clear();
  fallback_cells = unprojected_vertices = refined_patches = 0;
  patch = PatchStats{};
}

CellMesher::CellMesher(const Sampler& f, const CellPartition& partition, CellMesherSettings settings,
                       int resolution, int refinable_level, std::function<double(const Vec3&)> size_at,
                       bool uniform_sizes)
    : f_(f),
      part_(partition),
      settings_(settings),
      params_(projection_params(settings.projection, std::max(resolution, 1))),
      fixed_resolution_(resolution),
      refinable_level_(refinable_level),
      size_at_(std::move(size_at)),
      uniform_sizes_(uniform_sizes) {}

Mesh CellMesher::run(CellMesherCounters& counters, StageTimes* times) {
  {
    const StageTimer timer(times, "sides");
    collect_sides();
    compute_sides(counters);
  }
  const StageTimer timer(times, "patches");
  mesh_cells(counters);
  if (settings_.projection.vertex_roles) mesh_.set_attribute("role", roles_);
  return std::move(mesh_);
}

std::pair<int, int> CellMesher::segment_range() const {
  if (side_segments_.empty()) return {0, 0};
  const auto [lo, hi] = std::minmax_element(side_segments_.begin(), side_segments_.end());
  return {*lo, *hi};
}

/// Segments per side for a cell: the fixed resolution, or its size times side_factor(level) over the
/// smallest target size at its corners (at least 1), so cells of one level share one template
/// resolution and deeper cells get proportionally fewer segments.
int CellMesher::cell_resolution(std::size_t c) {
  if (fixed_resolution_ > 0) return fixed_resolution_;
  const PartitionCell& cell = part_.cells[c];
  double h = std::numeric_limits<double>::infinity();
  for (const CellLoop& loop : cell.loops)
    for (std::uint32_t k : loop.corners) h = std::min(h, corner_size(k));
  // The side factor never takes a cell down to one segment per side (a patch of corners only, whose
  // fans leave most vertices irregular) where the cell size alone gives two or more.
  const double r =
      std::max(std::round(cell.size * side_factor(cell.level) / h), std::min(2.0, std::round(cell.size / h)));
  return static_cast<int>(std::clamp(r, 1.0, static_cast<double>(PatchTemplate::kMaxResolution)));
}

/// The segment count of side i: the smallest resolution of the cells that share it, so the finer
/// neighbour keeps its regular template and the coarser one merges boundary vertices.
int CellMesher::side_segments(std::size_t i) {
  if (cell_resolutions_.empty()) cell_resolutions_.assign(part_.cells.size(), 0);
  int k = PatchTemplate::kMaxResolution;
  for (std::size_t c : side_cells_[i]) {
    if (cell_resolutions_[c] == 0) cell_resolutions_[c] = cell_resolution(c);
    k = std::min(k, cell_resolutions_[c]);
  }
  return k;
}

/// With uniform sizes: the mean length of the loop sides (corner to corner) of the cells at `level`
/// over their cell size, so that r = cell * factor / h gives edges of about h. A plane cuts a cube in
/// sides shorter than the cell (mean factor 0.7-0.8 on the public surfaces), and counts from the
/// cell alone gave mean edges of 0.66-0.97 h. 1 with a size field: there the margin of the error
/// bound (centroid distances 0.3-0.6 of it) comes from the shorter edges and is kept.
double CellMesher::side_factor(int level) {
  if (!uniform_sizes_) return 1.0;
  if (side_factors_.empty()) side_factors_.assign(static_cast<std::size_t>(kMaxPartitionLevel) + 1, 0.0);
  double& factor = side_factors_[static_cast<std::size_t>(level)];
  if (factor > 0.0) return factor;
  double sum = 0.0;
  std::size_t count = 0;
  for (const PartitionCell& cell : part_.cells) {
    if (cell.level != level) continue;
    for (const CellLoop& loop : cell.loops)
      for (std::size_t k = 0; k < loop.corners.size(); ++k) {
        const Vec3& a = part_.corners[loop.corners[k]].position;
        const Vec3& b = part_.corners[loop.corners[next(k, loop.corners.size())]].position;
        sum += (a - b).norm() / cell.size;
        ++count;
      }
  }
  factor = count > 0 && sum > 0.0 ? sum / static_cast<double>(count) : 1.0;
  return factor;
}

double CellMesher::corner_size(std::uint32_t c) const {
  return corner_sizes_[c];  // filled in parallel by compute_sides() before any cell asks
}

void CellMesher::collect_sides() {
  struct Use {
    Side side;
    std::size_t cell;
  };
  std::vector<Use> uses;
  for (std::size_t c = 0; c < part_.cells.size(); ++c)
    for (const CellLoop& loop : part_.cells[c].loops)
      for (std::size_t k = 0; k < loop.corners.size(); ++k) {
        const std::uint32_t a = loop.corners[k];
        const std::uint32_t b = loop.corners[next(k, loop.corners.size())];
        uses.push_back({Side{std::min(a, b), std::max(a, b), loop.side_faces[k]}, c});
      }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return std::tie(x.side.from, x.side.to, x.cell) < std::tie(y.side.from, y.side.to, y.cell);
  });
  for (const Use& use : uses) {
    if (sides_.empty() || sides_.back().from != use.side.from || sides_.back().to != use.side.to) {
      sides_.push_back(use.side);
      side_cells_.emplace_back();
    }
    side_cells_.back().push_back(use.cell);
  }
}

std::size_t CellMesher::side_index(std::uint32_t a, std::uint32_t b) const {
  const Side key{std::min(a, b), std::max(a, b), 0};
  const auto it = std::lower_bound(sides_.begin(), sides_.end(), key, [](const Side& x, const Side& y) {
    return std::tie(x.from, x.to) < std::tie(y.from, y.to);
  });
  if (it == sides_.end() || it->from != key.from || it->to != key.to)
    throw Error(ErrorKind::Internal, "projection: a loop side has no record");
  return static_cast<std::size_t>(it - sides_.begin());
}

void CellMesher::add_vertex(const Vec3& position, const Vec3& gradient, float role) {
  mesh_.positions.push_back(position);
  gradients_.push_back(gradient);
  roles_.push_back(role);
}

/// Phase 1: boundary vertices of every side; vertex ids: corners first, then sides in key order. The
/// segment counts come first (in order: they fill lazy caches), then the sides are sampled in parallel
/// and appended in key order, so the ids do not depend on the threads.
void CellMesher::compute_sides(CellMesherCounters& counters) {
  mesh_.positions.reserve(part_.corners.size());
  gradients_.reserve(part_.corners.size());
  roles_.reserve(part_.corners.size());
  for (const CellCorner& c : part_.corners)
    add_vertex(c.position, c.gradient, role_value(VertexRole::Corner));
  if (fixed_resolution_ == 0) {
    // The target size at every corner, in parallel (size_at_ evaluates the curvature with max_error).
    corner_sizes_.assign(part_.corners.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, part_.corners.size(), 256), [&](const auto& range) {
      settings_.budget.check_cancel();
      for (std::size_t c = range.begin(); c != range.end(); ++c)
        corner_sizes_[c] = size_at_(part_.corners[c].position);
    });
  }
  side_segments_.reserve(sides_.size());
  for (std::size_t i = 0; i < sides_.size(); ++i) side_segments_.push_back(side_segments(i));
  std::vector<SidePoints> sampled(sides_.size());
  if (needs_side_curves(base_kind())) side_curves_.assign(sides_.size(), {});
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sides_.size(), 64), [&](const auto& range) {
    settings_.budget.check_cancel();
    for (std::size_t i = range.begin(); i != range.end(); ++i) sampled[i] = sample(i, side_segments_[i]);
  });
  side_accepted_.reserve(sides_.size());
  side_offsets_.reserve(sides_.size());
  for (std::size_t i = 0; i < sides_.size(); ++i) {
    side_offsets_.push_back(mesh_.positions.size());
    const SidePoints& s = sampled[i];
    if (!s.accepted) {
      ++counters.rejected_sides;
      for (std::size_t cell : side_cells_[i])
        if (refinable(cell)) split_cells_.insert(cell);
    }
    side_accepted_.push_back(s.accepted);
    for (const SurfacePoint& p : s.points) add_vertex(p.position, p.gradient, role_value(VertexRole::Side));
    settings_.budget.check_vertices(mesh_.positions.size());
  }
}

/// Side i's inner boundary vertices; with the Coons base also its face curve, kept for the patches
/// (side_curves_[i]). Touches nothing but side_curves_[i]: sides are sampled in parallel.
SidePoints CellMesher::sample(std::size_t i, int segments) {
  const Side& side = sides_[i];
  const CellCorner& from = part_.corners[side.from];
  const CellCorner& to = part_.corners[side.to];
  const CellFace& face = part_.faces[side.face];
  ProjectionParams params = params_;
  params.resolution = segments;
  if (!needs_side_curves(base_kind())) return sample_side(f_, from, to, face, params);
  FaceCurve curve = trace_face_curve(f_, from, to, face, params);
  side_curves_[i] = std::move(curve.dense);
  return SidePoints{std::move(curve.points), curve.accepted};
}

/// The base surface of a loop, and the corner directions to blend (docs/algorithms.md 3.5, 4.5).
std::unique_ptr<BaseSurface> CellMesher::base_surface(const CellLoop& loop,
                                                      std::vector<Vec3>& directions) const {
  directions.clear();
  BaseInputs inputs;
  const bool curves = needs_side_curves(base_kind());
  for (std::size_t k = 0; k < loop.corners.size(); ++k) {
    const std::uint32_t a = loop.corners[k];
    inputs.corners.push_back(part_.corners[a].position);
    // Over traced curves, the unit gradients at the corners; else the cell-edge directions.
    directions.push_back(curves ? part_.corners[a].gradient.normalized() : part_.corners[a].direction);
    if (!curves) continue;
    const std::uint32_t b = loop.corners[next(k, loop.corners.size())];
    std::vector<Vec3> dense = side_curves_[side_index(a, b)];  // stored from the smaller corner id
    if (a > b) std::reverse(dense.begin(), dense.end());
    inputs.side_curves.push_back(std::move(dense));
  }
  return make_base_surface(base_kind(), std::move(inputs));
}

/// Global id of point i (0..k, counted from corner a; 0 and k are the corners) of the side from
/// corner a to b with k segments.
std::uint32_t CellMesher::side_vertex(std::uint32_t a, std::uint32_t b, int i) const {
  const std::size_t s = side_index(a, b);
  const int k = segments(s);
  if (i <= 0) return a;
  if (i >= k) return b;
  const std::size_t j = a < b ? static_cast<std::size_t>(i) : static_cast<std::size_t>(k - i);
  return static_cast<std::uint32_t>(side_offsets_[s] + (j - 1));
}

bool CellMesher::loop_sides_accepted(const CellLoop& loop) const {
  for (std::size_t k = 0; k < loop.corners.size(); ++k)
    if (!side_accepted_[side_index(loop.corners[k], loop.corners[next(k, loop.corners.size())])])
      return false;
  return true;
}

/// Phase 2: the cells in chunks; each chunk's cells are meshed in parallel into their own outputs,
/// then appended in cell order (new vertex ids in that order), so the mesh does not depend on the
/// threads. Chunks bound the memory held by outputs not yet appended.
void CellMesher::mesh_cells(CellMesherCounters& counters) {
  constexpr std::size_t kChunk = 4096;
  std::vector<CellOutput> outputs;
  for (std::size_t first = 0; first < part_.cells.size(); first += kChunk) {
    settings_.budget.check_cancel();
    if (settings_.budget.progress) settings_.budget.progress(Progress{first, part_.cells.size()});
    const std::size_t count = std::min(kChunk, part_.cells.size() - first);
    outputs.assign(count, CellOutput{});
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 16), [&](const auto& range) {
      settings_.budget.check_cancel();
      for (std::size_t k = range.begin(); k != range.end(); ++k) mesh_cell(first + k, outputs[k]);
    });
    for (std::size_t k = 0; k < count; ++k) append(first + k, outputs[k], counters);
    settings_.budget.check_vertices(mesh_.positions.size());
  }
}

/// Adds cell c's output: its new vertices get the next ids, its triangles refer to them.
void CellMesher::append(std::size_t c, const CellOutput& out, CellMesherCounters& counters) {
  if (out.split) split_cells_.insert(c);
  if (out.patch_sides > 0) ++counters.patches_by_sides[out.patch_sides];
  if (out.refined) ++counters.refined_patches;
  if (out.rejected) {
    ++counters.rejected_patches;
    ++counters.rejected_by_verdict[*out.rejected];
  }
  if (out.fan) ++counters.fallback_cells;
  counters.unprojected_vertices += out.unprojected;
  counters.patch.gradient_rays += out.patch.gradient_rays;
  counters.patch.clamped_base_points += out.patch.clamped_base_points;
  if (mesh_.positions.size() + out.points.size() >= kLocalVertex)
    throw LimitError("projection: more than 2^31 vertices", "max_vertices");
  const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
  for (std::size_t i = 0; i < out.points.size(); ++i)
    add_vertex(out.points[i].position, out.points[i].gradient, out.roles[i]);
  for (Triangle t : out.triangles) {
    for (std::uint32_t& v : t)
      if (v >= kLocalVertex) v = base + (v - kLocalVertex);
    mesh_.triangles.push_back(t);
  }
}

/// Phase 2 for one cell: a projected patch; when it fails, a request to split the cell or, where it
/// cannot be split, fans. Reads the mesher's state, writes only `out` (cells run in parallel).
void CellMesher::mesh_cell(std::size_t c, CellOutput& out) const {
  if (split_cells_.contains(c)) return;  // a side failed: the cell is refined anyway
  const PartitionCell& cell = part_.cells[c];
  const bool simple = !needs_refinement(cell) && cell.loops.front().corners.size() >= 3 &&
                      cell.loops.front().corners.size() <= static_cast<std::size_t>(Domain::kMaxSides);
  if (simple && loop_sides_accepted(cell.loops.front())) {
    const PatchVerdict verdict = mesh_patch(cell, cell.loops.front(), out);
    if (verdict == PatchVerdict::Accepted) {
      out.patch_sides = static_cast<int>(cell.loops.front().corners.size());
      out.refined = cell.level > part_.start_level;
      return;
    }
    out.rejected = verdict;
    out.points.clear();
    out.roles.clear();
    out.triangles.clear();
  }
  if (refinable(c)) {
    out.split = true;
    return;
  }
  out.fan = true;
  for (const CellLoop& loop : cell.loops) mesh_fan(cell, loop, out);
}

PatchVerdict CellMesher::mesh_patch(const PartitionCell& cell, const CellLoop& loop, CellOutput& out) const {
  const int n = static_cast<int>(loop.corners.size());
  // The template has as many segments per side as the loop's longest side count; a side with fewer
  // takes, for template vertex i, its point round(i k / r): coinciding template vertices merge and the
  // triangles between them vanish.
  int r = 1;
  for (std::size_t k = 0; k < loop.corners.size(); ++k)
    r = std::max(r, segments(side_index(loop.corners[k], loop.corners[next(k, loop.corners.size())])));
  const auto patch = patch_template(n, r, coordinate_kind(settings_.patch));
  std::vector<Vec3> d;
  const std::unique_ptr<BaseSurface> base = base_surface(loop, d);
  std::vector<std::uint32_t> ids(patch->vertex_count(), 0);
  std::vector<SurfacePoint> points(patch->vertex_count());
  for (std::size_t v = 0; v < patch->vertex_count(); ++v) {
    const VertexTag& tag = patch->tag(static_cast<int>(v));
    if (tag.kind == VertexTag::Kind::Interior) continue;
    const auto k = static_cast<std::size_t>(tag.side);
    const std::uint32_t a = loop.corners[k];
    const std::uint32_t b = loop.corners[next(k, loop.corners.size())];
    if (tag.kind == VertexTag::Kind::Corner) {
      ids[v] = a;
    } else {
      const int count = segments(side_index(a, b));
      ids[v] = side_vertex(a, b, (2 * tag.index * count + r) / (2 * r));
    }
    points[v] = {mesh_.positions[ids[v]], gradients_[ids[v]]};
  }
  const PatchVerdict verdict = project_patch(
      f_, *patch, *base, d, MarchRegion::cell(cell.bounds, cell.planes), params_, points, out.patch);
  if (verdict != PatchVerdict::Accepted) return verdict;
  for (std::size_t v = 0; v < patch->vertex_count(); ++v) {
    if (patch->tag(static_cast<int>(v)).kind != VertexTag::Kind::Interior) continue;
    ids[v] = kLocalVertex + static_cast<std::uint32_t>(out.points.size());
    const VertexRole role =
        static_cast<int>(v) == patch->centre() ? VertexRole::Centre : VertexRole::Interior;
    out.points.push_back(points[v]);
    out.roles.push_back(role_value(role));
  }
  for (const TemplateTriangle& t : patch->triangles()) {
    const Triangle tri{ids[static_cast<std::size_t>(t[0])], ids[static_cast<std::size_t>(t[1])],
                       ids[static_cast<std::size_t>(t[2])]};
    if (tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0]) out.triangles.push_back(tri);
  }
  return PatchVerdict::Accepted;
}

/// Fallback: the loop's boundary polygon (corners and shared side vertices) fanned around a centre
/// vertex moved onto f = 0 along the polygon's normal when a ray finds the surface near the cell.
void CellMesher::mesh_fan(const PartitionCell& cell, const CellLoop& loop, CellOutput& out) const {
  std::vector<std::uint32_t> polygon;
  for (std::size_t k = 0; k < loop.corners.size(); ++k) {
    const std::uint32_t a = loop.corners[k];
    const std::uint32_t b = loop.corners[next(k, loop.corners.size())];
    polygon.push_back(a);
    for (int i = 1; i < segments(side_index(a, b)); ++i) polygon.push_back(side_vertex(a, b, i));
  }
  std::vector<Vec3> positions;
  Vec3 normal = Vec3::Zero();
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    positions.push_back(mesh_.positions[polygon[k]]);
    normal += mesh_.positions[polygon[k]].cross(mesh_.positions[polygon[next(k, polygon.size())]]);
  }
  // The centre moves onto f = 0 along the polygon's normal, else along grad f, within the cell grown
  // by half its size (a fallback cell is a poor fit by definition; its fan must still close it).
  const Box& clip = part_.region;
  const Box region{(cell.bounds.lo - 0.5 * cell.bounds.size()).cwiseMax(clip.lo),
                   (cell.bounds.hi + 0.5 * cell.bounds.size()).cwiseMin(clip.hi)};
  const FanCentre centre = fan_centre(f_, positions, normal, MarchRegion::cell(region), params_.march_steps);
  if (!centre.projected) ++out.unprojected;
  const Vec3 position = centre.point.position;
  const Vec3 gradient = centre.point.gradient;
  const std::uint32_t c = kLocalVertex + static_cast<std::uint32_t>(out.points.size());
  out.points.push_back({position, gradient});
  out.roles.push_back(role_value(VertexRole::FanCentre));
  for (std::size_t k = 0; k < polygon.size(); ++k)
    out.triangles.push_back({c, polygon[k], polygon[next(k, polygon.size())]});
}

}  // namespace isopatch
