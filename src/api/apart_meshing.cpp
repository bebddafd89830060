// Shapes of surfaces that never meet, meshed one surface at a time (apart_meshing.hpp).
#include "api/apart_meshing.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include "csg/apart_operands.hpp"
#include "projection/convex_meshing.hpp"

namespace isopatch {

namespace {

/// Adds `part`'s counts to `into` (the first part's run, or nothing yet).
void add_part_stats(MeshStats& into, const MeshStats& part) {
  into.seconds += part.seconds;
  into.threads = std::max(into.threads, part.threads);
  into.value_evaluations += part.value_evaluations;
  into.gradient_evaluations += part.gradient_evaluations;
  into.vertices += part.vertices;
  into.triangles += part.triangles;
  into.times.merge(part.times);
  if (!into.projection) into.projection = part.projection;
  if (!into.marching_cubes) into.marching_cubes = part.marching_cubes;
  if (!into.refine) into.refine = part.refine;
  if (!into.local_sizes) into.local_sizes = part.local_sizes;
  if (into.creases && part.creases) {
    CreaseStats& c = *into.creases;
    const CreaseStats& o = *part.creases;
    for (auto [to, from] : {std::pair{&c.faces, o.faces},
                            {&c.creases, o.creases},
                            {&c.corners, o.corners},
                            {&c.seams, o.seams},
                            {&c.pieces, o.pieces},
                            {&c.smooth_pairs, o.smooth_pairs},
                            {&c.repair_moves, o.repair_moves},
                            {&c.interval_cells, o.interval_cells},
                            {&c.interval_creases, o.interval_creases},
                            {&c.uncertain_cells, o.uncertain_cells},
                            {&c.caps, o.caps},
                            {&c.crease_vertices, o.crease_vertices},
                            {&c.cut_planes, o.cut_planes}})
      *to += from;
    c.seconds += o.seconds;
  }
  if (!into.creases) into.creases = part.creases;
  if (into.cleanup && part.cleanup) into.cleanup->add_counts(*part.cleanup);
  if (!into.cleanup) into.cleanup = part.cleanup;
  MeshWarnings& w = into.warnings;
  const MeshWarnings& o = part.warnings;
  for (const auto& [reason, cells] : o.doubtful_cells_by_reason) w.doubtful_cells_by_reason[reason] += cells;
  w.doubtful_cells += o.doubtful_cells;
  w.doubtful_topology_cells += o.doubtful_topology_cells;
  w.doubtful_grazing_faces += o.doubtful_grazing_faces;
  w.doubtful_cell_size = std::max(w.doubtful_cell_size, o.doubtful_cell_size);
  w.depth_limit = std::max(w.depth_limit, o.depth_limit);
  if (o.error_bound_violations)
    w.error_bound_violations = w.error_bound_violations.value_or(0) + *o.error_bound_violations;
  w.fan_patches += o.fan_patches;
  w.unprojected_fan_centres += o.unprojected_fan_centres;
  w.exempt_corners += o.exempt_corners;
  if (w.uncertain_crease_cells == 0) w.uncertain_crease_near = o.uncertain_crease_near;
  w.uncertain_crease_cells += o.uncertain_crease_cells;
  w.creases_leave_box = std::max(w.creases_leave_box, o.creases_leave_box);
  w.creases_in_partition = std::max(w.creases_in_partition, o.creases_in_partition);
  w.creases_rounded = std::max(w.creases_rounded, o.creases_rounded);
  if (o.creases_finer_edge > 0.0)
    w.creases_finer_edge = w.creases_finer_edge > 0.0 ? std::min(w.creases_finer_edge, o.creases_finer_edge)
                                                      : o.creases_finer_edge;
  if (w.crease_failure.empty()) w.crease_failure = o.crease_failure;
}

/// `b` appended to `a` (its indices shifted); attributes only when both have the same ones.
void append(Mesh& a, Mesh&& b) {
  const auto offset = static_cast<std::uint32_t>(a.positions.size());
  if (a.positions.empty()) {
    a = std::move(b);
    return;
  }
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  for (Triangle t : b.triangles) {
    for (auto& v : t) v += offset;
    a.triangles.push_back(t);
  }
  const bool same =
      a.attributes.size() == b.attributes.size() &&
      std::equal(a.attributes.begin(), a.attributes.end(), b.attributes.begin(),
                 [](const VertexAttribute& x, const VertexAttribute& y) { return x.name == y.name; });
  if (!same) {
    a.attributes.clear();
    return;
  }
  for (std::size_t i = 0; i < a.attributes.size(); ++i)
    a.attributes[i].values.insert(a.attributes[i].values.end(), b.attributes[i].values.begin(),
                                  b.attributes[i].values.end());
}

/// The root of `v` in the forest `parent` (paths halved on the way).
std::uint32_t root_of(std::vector<std::uint32_t>& parent, std::uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

/// `mesh` without the components (sets of triangles joined by vertices) where `judge`, read at the
/// component's vertex farthest from judge = 0, lacks the sign `keep_sign`; vertices no triangle keeps are
/// removed, the rest keep their order.
Mesh kept_components(Mesh mesh, const Surface& judge, int keep_sign) {
  const std::size_t n = mesh.positions.size();
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const Triangle& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) parent[root_of(parent, t[k])] = root_of(parent, t[0]);
  std::vector<double> farthest(n, 0.0);  // per root: the judge's value of largest magnitude
  for (std::uint32_t v = 0; v < n; ++v) {
    const double value = judge.value(mesh.positions[v]);
    double& f = farthest[root_of(parent, v)];
    if (std::isfinite(value) && std::abs(value) > std::abs(f)) f = value;
  }
  std::vector<std::int64_t> index(n, -1);
  std::vector<Triangle> triangles;
  for (const Triangle& t : mesh.triangles) {
    const double f = farthest[root_of(parent, t[0])];
    if (!(keep_sign < 0 ? f < 0.0 : f > 0.0)) continue;
    triangles.push_back(t);
    for (const std::uint32_t v : t) index[v] = 0;
  }
  Mesh out;
  for (std::uint32_t v = 0; v < n; ++v)
    if (index[v] == 0) {
      index[v] = static_cast<std::int64_t>(out.positions.size());
      out.positions.push_back(mesh.positions[v]);
    }
  for (Triangle t : triangles) {
    for (auto& v : t) v = static_cast<std::uint32_t>(index[v]);
    out.triangles.push_back(t);
  }
  for (VertexAttribute& a : mesh.attributes) {
    VertexAttribute kept{a.name, {}};
    for (std::uint32_t v = 0; v < n; ++v)
      if (index[v] >= 0) kept.values.push_back(a.values[v]);
    out.attributes.push_back(std::move(kept));
  }
  return out;
}

}  // namespace

Box apart_domain(const Surface& f, const Settings& settings) {
  const Box box = settings.box ? *settings.box : convex_meshing_box(f, settings).value_or(f.box());
  if (!settings.frame) return box;
  double reach = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? box.hi.x() : box.lo.x(), (corner & 2) ? box.hi.y() : box.lo.y(),
                 (corner & 4) ? box.hi.z() : box.lo.z());
    reach = std::max(reach, p.norm());
  }
  return Box{Vec3::Constant(-reach), Vec3::Constant(reach)};
}

Mesh mesh_apart_surfaces(std::span<const ApartSurface> parts, const Settings& settings, MeshStats* stats,
                         const WallMesher& mesh_part, std::size_t* surfaces) {
  const auto start = std::chrono::steady_clock::now();
  const MeshStats before = stats ? *stats : MeshStats{};
  Mesh mesh;
  MeshStats total = before;
  std::size_t meshed = 0, with_triangles = 0;
  std::exception_ptr no_surface;
  for (const ApartSurface& part : parts) {
    // Each later part gets what the earlier ones left of the run's budgets.
    Settings s = settings;
    if (settings.max_vertices > 0) {
      settings.check_vertices(mesh.positions.size() + 1);
      s.max_vertices = settings.max_vertices - mesh.positions.size();
    }
    if (settings.max_evaluations > 0) {
      const std::uint64_t spent = total.value_evaluations + total.gradient_evaluations -
                                  before.value_evaluations - before.gradient_evaluations;
      s.max_evaluations = spent < settings.max_evaluations ? settings.max_evaluations - spent : 1;
    }
    if (settings.time_limit > 0.0) {
      const double used = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      s.time_limit = std::max(1e-3, settings.time_limit - used);
    }
    // The first part's run adds to the caller's statistics as a plain run would; the others' are added.
    MeshStats own = meshed == 0 ? before : MeshStats{};
    own.sheet.reset();
    try {
      Mesh piece = mesh_part(*part.surface, s, &own);
      if (part.judge) piece = kept_components(std::move(piece), *part.judge, part.keep_sign);
      const std::size_t pieces = piece.triangles.empty() ? 0 : (own.sheet ? own.sheet->walls : 1);
      append(mesh, std::move(piece));
      with_triangles += pieces;  // a part that is a sheet itself has two surfaces
      if (meshed == 0)
        total = std::move(own);
      else
        add_part_stats(total, own);
      ++meshed;
    } catch (const NoSurfaceError&) {
      if (!no_surface) no_surface = std::current_exception();
    }
  }
  if (meshed == 0) std::rethrow_exception(no_surface);
  if (mesh.triangles.empty())
    throw NoSurfaceError(
        "no surface in the box: every surface of the shape lies outside its other solid (the "
        "intersection is empty, or the union is the whole box)");
  total.vertices = mesh.positions.size();
  total.triangles = mesh.triangles.size();
  if (surfaces) *surfaces = with_triangles;
  if (stats) *stats = std::move(total);
  return mesh;
}

std::optional<Mesh> mesh_apart_operands(const Surface& f, const Settings& settings, MeshStats* stats,
                                        const WallMesher& mesh_part) {
  if (settings.method != Method::Projection) return std::nullopt;
  const Box domain = apart_domain(f, settings);
  const double finest = 0.25 * default_edge_length(settings, settings.box.value_or(f.box()));
  const std::optional<ApartOperands> split = split_apart_operands(f, domain, finest, 1u << 18);
  if (!split) return std::nullopt;
  // max(a, b): a's surface where b < 0 and b's where a < 0; min(a, b): where the other is positive.
  const int keep = split->united ? 1 : -1;
  const ApartSurface parts[2] = {{split->operands[0], split->operands[1], keep},
                                 {split->operands[1], split->operands[0], keep}};
  return mesh_apart_surfaces(parts, settings, stats, mesh_part);
}

}  // namespace isopatch
