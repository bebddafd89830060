// A sheet meshed as its two walls (sheet_meshing.hpp).
#include "api/sheet_meshing.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <utility>

#include "csg/sheet_shape.hpp"
#include "projection/convex_meshing.hpp"

namespace isopatch {

namespace {

/// Where the walls must stay apart: the meshing box, or for a frame every rotation of it about the
/// origin (the cube around the origin that holds the box's farthest corner).
Box checked_domain(const Surface& f, const Settings& settings) {
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

/// Adds `wall`'s counts to `into` (the first wall's run, or nothing yet).
void add_wall_stats(MeshStats& into, const MeshStats& wall) {
  into.seconds += wall.seconds;
  into.threads = std::max(into.threads, wall.threads);
  into.value_evaluations += wall.value_evaluations;
  into.gradient_evaluations += wall.gradient_evaluations;
  into.vertices += wall.vertices;
  into.triangles += wall.triangles;
  into.times.merge(wall.times);
  if (!into.projection) into.projection = wall.projection;
  if (!into.marching_cubes) into.marching_cubes = wall.marching_cubes;
  if (!into.refine) into.refine = wall.refine;
  if (!into.local_sizes) into.local_sizes = wall.local_sizes;
  if (!into.creases) into.creases = wall.creases;
  if (into.cleanup && wall.cleanup) into.cleanup->add_counts(*wall.cleanup);
  if (!into.cleanup) into.cleanup = wall.cleanup;
  MeshWarnings& w = into.warnings;
  const MeshWarnings& o = wall.warnings;
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

}  // namespace

std::optional<std::array<SurfacePtr, 2>> sheet_walls(const Surface& f, const Settings& settings) {
  if (settings.method != Method::Projection) return std::nullopt;
  const std::optional<SheetShape> sheet = split_sheet_shape(f, checked_domain(f, settings));
  if (!sheet) return std::nullopt;
  return sheet->walls;
}

std::optional<Mesh> mesh_sheet(const Surface& f, const Settings& settings, MeshStats* stats,
                               const WallMesher& mesh_wall) {
  const std::optional<std::array<SurfacePtr, 2>> sheet = sheet_walls(f, settings);
  if (!sheet) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  const MeshStats before = stats ? *stats : MeshStats{};
  Mesh mesh;
  MeshStats total = before;
  std::size_t walls = 0, surfaces = 0;
  std::exception_ptr no_surface;
  for (const SurfacePtr& wall : *sheet) {
    // The second wall gets what the first left of the run's budgets.
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
    // The first wall's run adds to the caller's statistics as a plain run would; the second's are added.
    MeshStats own = walls == 0 ? before : MeshStats{};
    own.sheet.reset();
    try {
      append(mesh, mesh_wall(*wall, s, &own));
      surfaces += own.sheet ? own.sheet->walls : 1;  // a wall that is a sheet itself has two
      if (walls == 0)
        total = std::move(own);
      else
        add_wall_stats(total, own);
      ++walls;
    } catch (const NoSurfaceError&) {
      if (!no_surface) no_surface = std::current_exception();
    }
  }
  if (walls == 0) std::rethrow_exception(no_surface);
  total.vertices = mesh.positions.size();
  total.triangles = mesh.triangles.size();
  total.sheet = SheetStats{surfaces};
  if (stats) *stats = std::move(total);
  return mesh;
}

}  // namespace isopatch
