// The single entry point: dispatch on Settings::method.
#include <isopatch/error.hpp>
#include <isopatch/fairing.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/remesh.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/apart_meshing.hpp"
#include "api/capped_curved_cut.hpp"
#include "api/capped_meshing.hpp"
#include "api/clipped_creases.hpp"
#include "api/crease_meshing.hpp"
#include "api/curvature_feature_sizes.hpp"
#include "api/curved_cut.hpp"
#include "api/cut_feature_sizes.hpp"
#include "api/finer_edge_retry.hpp"
#include "api/frame_meshing.hpp"
#include "api/multiresolution.hpp"
#include "api/sheet_meshing.hpp"
#include "api/size_estimate.hpp"
#include "api/task_arena_run.hpp"
#include "api/time_share.hpp"
#include "core/point_grid.hpp"
#include "projection/convex_meshing.hpp"
#include "remesh/remesh_presets.hpp"
#include "surface/budgeted_surface.hpp"
#include "surface/singular_level_set.hpp"
#include "surface/target_size.hpp"
#include "surface/zero_function.hpp"

namespace isopatch {

namespace {

/// The median edge length of `mesh` (0 for a mesh without triangles).
double median_edge_length(const Mesh& mesh) {
  std::vector<double> lengths;
  lengths.reserve(mesh.triangles.size() * 3);
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      lengths.push_back((mesh.positions[t[static_cast<std::size_t>(i)]] -
                         mesh.positions[t[static_cast<std::size_t>((i + 1) % 3)]])
                            .norm());
  if (lengths.empty()) return 0.0;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2),
                   lengths.end());
  return lengths[lengths.size() / 2];
}

/// The remeshing settings derived from the mesher's: the requested edge length (else the output's
/// median edge length) or, with max_error or a size_field, the varying sizes of target_size.hpp.
RemeshSettings remesh_settings(const Mesh& mesh, const Box& box, const Settings& s, int iterations) {
  RemeshSettings r = preset_remesh_settings(s, iterations);
  r.box = box;
  r.cut_planes = s.region;
  // The projection mesher's sizes, shared; only where uniform sizes were not asked for by length does
  // the clean-up follow the output's median edge instead of the default length.
  r.sizes = target_sizes(s, box);
  if (!r.sizes.varies() && !s.edge_length) r.sizes.largest = median_edge_length(mesh);
  return r;
}

/// Applies the surface-bound clean-up of remesh.hpp when Settings asks for it (see remesh_iterations).
void clean_up(Mesh& mesh, const Surface& surface, const Settings& settings, MeshStats* stats) {
  const int iterations = settings.remesh_iterations.value_or(
      settings.method == Method::Projection ? kDefaultRemeshIterations : 0);
  if (iterations == 0 || mesh.triangles.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  const Box box = settings.box.value_or(surface.box());
  const RemeshStats r = remesh_on_surface(mesh, surface, remesh_settings(mesh, box, settings, iterations));
  if (!stats) return;
  stats->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats->gradient_evaluations += r.gradient_evaluations;
  stats->times.merge(r.times);
  stats->vertices = mesh.vertex_count();
  stats->triangles = mesh.triangle_count();
  stats->cleanup = r;
  if (settings.max_error) stats->warnings.error_bound_violations = r.error_bound_violations;
}

/// Sizes that shrink where the box or a region plane cuts f = 0 in features smaller than an edge
/// (cut_feature_sizes.hpp), where f = 0 turns within an edge (curvature_feature_sizes.hpp) and around
/// SizeSettings::refine_around: the settings with that size field (the edge length made explicit, so the
/// rest of the mesh keeps it, and its smallest size, so the octree can deepen), or nullopt when there are
/// no such features or when one size was asked for (uniform, a fixed resolution, the paper's method alone,
/// marching cubes).
struct LocalRefinement {
  Settings settings;
  std::shared_ptr<const GradedSizes> sizes;
  double edge = 0.0;
  std::size_t cut_sources = 0;        ///< of the sizes' sources, those from the cut
  std::size_t curvature_sources = 0;  ///< those where f = 0 turns within an edge (the rest: refine_around)
};
std::optional<LocalRefinement> local_refinement(const Surface& surface, const Settings& settings,
                                                const Box& box) {
  if (settings.uniform || settings.method != Method::Projection || settings.resolution != 0 ||
      settings.remesh_iterations.value_or(1) == 0)
    return std::nullopt;
  const double edge = default_edge_length(settings, box);
  const double smallest = std::min(target_sizes(settings, box).smallest, edge);
  std::vector<SizeSource> sources;
  if (settings.cut_sizes) sources = cut_feature_sources(surface, box, settings.region, edge, smallest);
  const std::size_t cut_sources = sources.size();
  // Rims and tubes thinner than an edge may ask for sizes below the usual floor (1/2048 of the box),
  // down to a share of the edge length: the octree then deepens to follow them.
  const double rim_floor = std::min(smallest, edge * CurvatureFeatureParams{}.finest_share);
  std::vector<SizeSource> rims = curvature_feature_sources(surface, box, edge, rim_floor).sources;
  // Near a given singular point the curvature grows without bound: there the stated depth of
  // refine_around decides, not the curvature (within two edge lengths of it).
  if (!settings.refine_around.empty()) {
    PointGrid near(2.0 * edge);
    for (std::size_t i = 0; i < settings.refine_around.size(); ++i) near.insert(settings.refine_around[i], i);
    std::erase_if(rims, [&](const SizeSource& s) {
      bool close = false;
      near.near(s.point, [&](std::size_t i) {
        close = close || (s.point - settings.refine_around[i]).norm() < 2.0 * edge;
      });
      return close;
    });
  }
  const std::size_t curvature_sources = rims.size();
  sources.insert(sources.end(), rims.begin(), rims.end());
  const double around = std::max(smallest, std::ldexp(edge, -settings.refine_around_depth));
  for (const Vec3& p : settings.refine_around)
    if (box.contains(p, 1e-9 * box.diagonal()) && around < edge) sources.push_back({p, around});
  if (sources.empty()) return std::nullopt;
  auto cut = std::make_shared<const GradedSizes>(std::move(sources), edge, CutFeatureParams{}.grading);
  LocalRefinement r{settings, cut, edge, cut_sources, curvature_sources};
  r.settings.edge_length = edge;
  r.settings.smallest_size = cut->smallest();
  r.settings.size_field = [cut, user = settings.size_field](const Vec3& p) {
    return user ? std::min(cut->at(p), user(p)) : cut->at(p);
  };
  return r;
}

/// What the local sizes did to `mesh`: about how many vertices they added (a vertex of size s takes the
/// area of (s / edge)^2 vertices of the edge length, so it adds 1 - (s / edge)^2), where, and how small.
LocalSizes local_sizes_report(const LocalRefinement& r, const Mesh& mesh) {
  LocalSizes l;
  l.sources = r.cut_sources;
  l.curvature_sources = r.curvature_sources;
  l.around = r.sizes->source_count() - r.cut_sources - r.curvature_sources;
  l.smallest_size = r.sizes->smallest();
  l.extent = r.sizes->extent();
  double added = 0.0;
  for (const Vec3& p : mesh.positions) {
    const double s = std::min(r.sizes->at(p), r.edge) / r.edge;
    added += 1.0 - s * s;
  }
  l.added_vertices = static_cast<std::size_t>(std::llround(added));
  return l;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Meshes with the method of `settings`, then cleans up (remesh.hpp) when asked.
Mesh dispatch_in_box(const Surface& surface, const Settings& settings, MeshStats* stats);

/// The projection mesher and its clean-up, multiresolution by default (multiresolution.hpp), in `box`.
Mesh mesh_by_projection(const Surface& surface, const Settings& settings, const Box& box, MeshStats* stats);

/// Meshes in the frame of the settings, or in the coordinate axes.
Mesh dispatch(const Surface& surface, const Settings& settings, MeshStats* stats) {
  // A region or given cells decide the box when none is given (in the user's coordinates, also for a
  // frame: the region is then inside that box in the frame too).
  if (const std::optional<Box> box = convex_meshing_box(surface, settings); box && !settings.box) {
    Settings s = settings;
    s.box = *box;
    return dispatch(surface, s, stats);
  }
  if (settings.frame) return mesh_in_frame(surface, settings, stats, dispatch);
  return dispatch_in_box(surface, settings, stats);
}

Mesh dispatch_in_box(const Surface& surface, const Settings& settings, MeshStats* stats) {
  // f = 0 everywhere is no surface, and neither mesher could tell quickly (see zero_function.hpp).
  const Box box = settings.box.value_or(surface.box());
  const auto checks_start = std::chrono::steady_clock::now();
  reject_zero_function(surface, box);
  // Projection and every clean-up follow grad f; marching cubes alone needs only signs.
  const bool uses_gradient = settings.method == Method::Projection || settings.fair_iterations > 0 ||
                             settings.remesh_iterations.value_or(0) > 0;
  if (uses_gradient) reject_singular_level_set(surface, box);
  // The searches before meshing count in the statistics (added once the mesher has set them).
  const double checks = seconds_since(checks_start);
  const auto add_before = [stats](const char* stage, double seconds) {
    if (!stats) return;
    stats->times.add(stage, seconds);
    stats->seconds += seconds;
  };
  switch (settings.method) {
    case Method::MarchingCubes: {
      Mesh mesh = marching_cubes(surface, settings, stats);
      add_before("surface_checks", checks);
      if (settings.fair_iterations > 0) {
        const auto start = std::chrono::steady_clock::now();
        const FairingStats fairing = laplace_fair(mesh, surface, settings.fair_iterations);
        if (stats) {
          stats->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          stats->gradient_evaluations += fairing.gradient_evaluations;
          stats->fairing = FairingSummary{settings.fair_iterations, fairing.unconverged};
        }
      }
      clean_up(mesh, surface, settings, stats);
      return mesh;
    }
    case Method::Projection: {
      const auto search_start = std::chrono::steady_clock::now();
      const std::optional<LocalRefinement> local = local_refinement(surface, settings, box);
      const double search = seconds_since(search_start);
      Mesh mesh = mesh_by_projection(surface, local ? local->settings : settings, box, stats);
      if (stats && local) stats->local_sizes = local_sizes_report(*local, mesh);
      add_before("surface_checks", checks);
      add_before("feature_search", search);
      return mesh;
    }
  }
  throw Error(ErrorKind::Internal, "unknown method");
}

Mesh mesh_by_projection(const Surface& surface, const Settings& settings, const Box& box, MeshStats* stats) {
  // The automatic level leaves the paper's method alone (remesh_iterations = 0) unrefined.
  const bool refine =
      settings.refine > 1 || (settings.refine == 0 && settings.remesh_iterations.value_or(1) > 0);
  // The automatic level's first guess, from the coarse grid's curvature.
  const bool first_guess = refine && level_from_curvature(settings);
  SizeEstimate estimate;
  const auto estimate_start = std::chrono::steady_clock::now();
  if (settings.max_vertices > 0 || first_guess) {
    estimate = estimate_size(surface, settings, box, first_guess);
    check_estimated_size(estimate, settings, box);
  }
  const double estimating = seconds_since(estimate_start);
  const auto one_level = [&surface](const Settings& s, MeshStats* st) {
    Mesh level = mesh_projection(surface, s, st);
    clean_up(level, surface, s, st);
    return level;
  };
  Mesh mesh =
      refine ? mesh_multiresolution(surface, settings, stats, one_level, first_guess ? &estimate : nullptr)
             : one_level(settings, stats);
  if (stats) {
    stats->value_evaluations += estimate.value_evaluations;
    stats->gradient_evaluations += estimate.gradient_evaluations;
    stats->times.add("size_estimate", estimating);
    stats->seconds += estimating;
  }
  return mesh;
}

/// What the cut-open crease path did: a mesh, or whether the shape has creases the partition's settings
/// would round (for the warning) and whether it was tried (its statistics then to be reset).
struct ClippedAttempt {
  std::optional<Mesh> mesh;
  bool has_creases = false;
  bool tried = false;
};

/// The shape cut open along its creases (clipped_creases.hpp) when it has creases and a region, a frame
/// or (`leaves_box`) creases leaving the box ask for it; given cells keep the partition's smooth mesh.
/// A failure of that path leaves the smooth mesh to the caller (with the warning).
ClippedAttempt mesh_cut_open_along_creases(const Surface& surface, const Settings& settings, MeshStats* stats,
                                           bool leaves_box) {
  ClippedAttempt out;
  if (settings.creases == Creases::Off || settings.method != Method::Projection || !surface.expression())
    return out;
  const bool partition = !settings.region.empty() || settings.frame || !settings.cells.empty();
  if (!partition && !leaves_box) return out;
  out.has_creases = leaves_box;
  if (!out.has_creases) {
    Settings plain = settings;
    plain.region.clear();
    plain.cells.clear();
    plain.frame.reset();
    plain.box = settings.box ? *settings.box : convex_meshing_box(surface, settings).value_or(surface.box());
    try {
      std::optional<Vec3> leaves;
      out.has_creases = analyse_creases(surface, plain, &leaves).has_value() || leaves.has_value();
      leaves_box = leaves.has_value();
    } catch (const CreaseError&) {
      out.has_creases = true;
    } catch (const Error&) {  // the check only informs: its budget or time running out changes nothing
    }
  }
  if (!out.has_creases || !settings.cells.empty()) return out;
  out.tried = true;
  // The run's own statistics, given to the caller only when its mesh is kept.
  MeshStats own = stats ? *stats : MeshStats{};
  try {
    CreasedMesh cut =
        mesh_clipped_along_creases(surface, cutting_planes(surface, settings, leaves_box), settings, &own);
    if (!cut.mesh && cut.creases_leave_box && !leaves_box) {
      own = stats ? *stats : MeshStats{};
      cut = mesh_clipped_along_creases(surface, cutting_planes(surface, settings, true), settings, &own);
    }
    // Pieces closed by fans are where the crease path failed (their triangles may cross): the
    // partition's smooth mesh, with its warning, is then the better answer.
    if (cut.mesh && own.warnings.fan_patches == 0) {
      out.mesh = std::move(cut.mesh);
      if (stats) *stats = std::move(own);
    }
  } catch (const CreaseError&) {
  }
  return out;
}

}  // namespace

namespace {

/// A refusal of the crease paths with what would mesh the shape, in the command line's words (the Python
/// package puts them in its own): where a face could not be cut into pieces, that this fails on faces of
/// many handles and at features near the edge length; where the cause is a feature near the edge length,
/// half the edge; always, turning creases off.
std::string with_remedies(const std::string& what, double edge) {
  const auto has = [&what](const char* words) { return what.find(words) != std::string::npos; };
  char half[32];
  std::snprintf(half, sizeof half, "%.3g", 0.5 * edge);
  std::string out = what;
  if (has("seam") || has("disc-like") || has("could not be cut")) {
    out +=
        "; the general crease path cuts each face into pieces by planes, which fails on a face of many "
        "handles (a lattice is meshed along its creases when capped by planes alone or cut by one curved "
        "solid alone: docs/lattices.md) and at features near the edge length (a smaller --edge-length ";
    out += half;
    out += ")";
  } else if ((has("than an edge") || has("too short") || has("narrower")) && !has("--edge-length")) {
    // A message that already ends by asking for a smaller edge length gets the length itself there.
    const std::string bare = "; a smaller edge length";
    if (out.size() >= bare.size() && out.compare(out.size() - bare.size(), bare.size(), bare) == 0)
      out.erase(out.size() - bare.size());
    out += "; a smaller edge length (--edge-length ";
    out += half;
    out += ") may mesh it";
  }
  if (!has("creases off"))
    out += "; turning creases off (--creases off) meshes it as a smooth surface (creases rounded)";
  return out;
}

Mesh mesh_in_stages(const Surface& surface, const Settings& given, MeshStats* stats) {
  // Each stage below gets what the earlier ones left of the time limit.
  const TimeShare time(given);
  // A sheet (the wall of a lattice, abs(g) - t) is its two walls, each meshed on its own, whatever the
  // sheet's thickness against the edge; a wall with creases is meshed along them.
  if (std::optional<Mesh> sheet = mesh_sheet(surface, time.next(), stats, mesh_surface))
    return std::move(*sheet);
  // A smooth solid capped by planes is the cut surface closed by caps; where its caps cannot close (a
  // plane tangent to the surface on the cut), the general crease path meshes it.
  const MeshStats before = stats ? *stats : MeshStats{};
  // A CSG shape whose faces are all trimmed away (an intersection or a difference that is empty, or
  // thinner than the edge everywhere) leaves no triangle: refused as the smooth path refuses a box that
  // f = 0 does not cross, never an empty mesh.
  const auto not_empty = [](Mesh mesh) {
    if (mesh.triangles.empty())
      throw NoSurfaceError(
          "no surface in the box: the faces of the shape leave no triangle where its solids meet (the "
          "intersection or difference is empty, or thinner than an edge everywhere; a smaller "
          "--edge-length finds a part thinner than the edge)");
    return mesh;
  };
  std::string cut_failure;
  bool cut_is_shape_fault = false;  // the two solids meet tangentially: not a 2-manifold
  // Two smooth solids capped by planes across the axes (a lattice in a cylinder capped at both ends): cut
  // open by the planes' box, closed by planar caps. Where that fails, the paths below are tried.
  try {
    if (std::optional<Mesh> cut = mesh_capped_curved_cut(surface, time.next(), stats))
      return not_empty(std::move(*cut));
  } catch (const CreaseError& e) {
    cut_failure = e.what();
    cut_is_shape_fault = dynamic_cast<const ShapeNotManifoldError*>(&e) != nullptr;
    if (stats) *stats = before;
  }
  try {
    if (std::optional<Mesh> capped = mesh_capped_shape(surface, time.next(), stats))
      return not_empty(std::move(*capped));
  } catch (const CreaseError&) {
    if (stats) *stats = before;
  }
  // A union with the outside of a polyhedron (min(g, -P): the lattice and the hollow of a skin) is the
  // capped solid max(-g, P) turned over.
  try {
    if (std::optional<Mesh> complement = mesh_capped_complement(surface, time.next(), stats))
      return not_empty(std::move(*complement));
  } catch (const CreaseError&) {
    if (stats) *stats = before;
  }
  // Two solids whose surfaces never meet (a lattice with a void inside a curved skin, parts side by
  // side): each surface meshed on its own by whichever path fits it, the components the other keeps.
  // Where a part cannot be meshed along its creases, the paths below try the whole.
  try {
    if (std::optional<Mesh> apart = mesh_apart_operands(surface, time.next(), stats, mesh_surface))
      return std::move(*apart);
  } catch (const CreaseError&) {
    if (stats) *stats = before;
  }
  // Two smooth solids intersected (a lattice cut by a sphere) are their trimmed faces joined along the
  // crease, whatever the faces' genus; where they cannot be joined, the general crease path meshes them.
  try {
    if (std::optional<Mesh> cut = mesh_curved_cut(surface, time.next(), stats))
      return not_empty(std::move(*cut));
  } catch (const CreaseError& e) {
    cut_failure = e.what();
    cut_is_shape_fault = dynamic_cast<const ShapeNotManifoldError*>(&e) != nullptr;
    if (stats) *stats = before;
  }
  // Every refusal says what would mesh the shape. A shape that is no 2-manifold is refused; where the
  // crease paths reach their own limits (a face they cannot cut into pieces), the shape is meshed as a
  // smooth surface with the reason in its warnings, unless creases were asked to be exact.
  const double edge = default_edge_length(given, given.box.value_or(surface.box()));
  std::string crease_failure;
  CreasedMesh creased;
  try {
    creased = mesh_along_creases(surface, time.next(), stats);
  } catch (const ShapeNotManifoldError& e) {
    // Two smooth solids whose join failed for another reason than a tangency are a 2-manifold: the
    // general path's verdict there is its own failure to cut a face of many handles, not a fault of the
    // shape. The join's reason stands, as any crease path's failure.
    if (cut_failure.empty() || cut_is_shape_fault) throw ShapeNotManifoldError(with_remedies(e.what(), edge));
    crease_failure = cut_failure;
    if (stats) *stats = before;
  } catch (const CreaseError& e) {
    // For two solids intersected, why their join failed.
    crease_failure = cut_failure.empty() ? std::string(e.what()) : cut_failure;
    if (stats) *stats = before;
  }
  if (creased.mesh) return not_empty(std::move(*creased.mesh));
  if (!crease_failure.empty()) {
    // A feature at the edge's scale: the shape along its creases at half the edge, before a rounded mesh
    // or a refusal.
    if (std::optional<Mesh> finer =
            mesh_at_half_edge(surface, time.next(), stats, crease_failure, edge, mesh_surface))
      return not_empty(std::move(*finer));
    if (given.creases == Creases::Exact) throw CreaseError(with_remedies(crease_failure, edge));
  }
  // A shape with creases cut open by a region, or by the box where its creases leave it, or seen
  // through a frame: meshed along its creases, cut open exactly (clipped_creases.hpp).
  const ClippedAttempt clipped =
      crease_failure.empty()
          ? mesh_cut_open_along_creases(surface, time.next(), stats, creased.creases_leave_box)
          : ClippedAttempt{};
  if (clipped.mesh) return not_empty(std::move(*clipped.mesh));
  if (stats && clipped.tried) *stats = before;
  // Exact creases asked for and none of the crease paths could follow them: refused, never rounded.
  if (given.creases == Creases::Exact && (creased.creases_leave_box || clipped.has_creases)) {
    throw CreaseError(with_remedies(
        creased.creases_leave_box
            ? "creases of the shape leave the box, and the shape cut open by the box could not be meshed "
              "along them; a box that holds the whole shape may mesh it along its creases"
            : "the shape cut by the region, seen through the frame or in the given cells could not be meshed "
              "along its creases; without the region, frame or cells it may be",
        edge));
  }
  const Settings settings = time.next();
  Mesh mesh = run_in_task_arena(settings, stats, [&] {
    if (settings.max_evaluations == 0 && settings.time_limit == 0.0)
      return dispatch(surface, settings, stats);
    const BudgetedSurface budgeted(surface, settings.max_evaluations, settings.time_limit);
    return dispatch(budgeted, settings, stats);
  });
  // Never a silent smooth mesh of a shape with creases: say why they were rounded.
  if (stats && creased.creases_leave_box) stats->warnings.creases_leave_box = 1;
  if (stats && !creased.creases_leave_box && clipped.has_creases) stats->warnings.creases_in_partition = 1;
  if (stats && !crease_failure.empty()) {
    stats->warnings.creases_rounded = 1;
    stats->warnings.crease_failure = crease_failure;
  }
  return mesh;
}

}  // namespace

Mesh mesh_surface(const Surface& surface, const Settings& settings, MeshStats* stats) {
  settings.validate();
  try {
    return mesh_in_stages(surface, settings, stats);
  } catch (const LimitError& e) {
    // A stage stopped at what the earlier ones left: the error names the limit the caller set.
    if (e.setting() != "time_limit" || settings.time_limit <= 0.0) throw;
    throw LimitError("the time limit of " + std::to_string(settings.time_limit) + " s is exceeded",
                     "time_limit");
  }
}

Method parse_method(const std::string& name) {
  if (name == "projection") return Method::Projection;
  if (name == "mc" || name == "marching-cubes") return Method::MarchingCubes;
  throw SettingError("method", "unknown method '" + name + "' (want projection or mc)");
}

std::string method_name(Method method) {
  switch (method) {
    case Method::Projection:
      return "projection";
    case Method::MarchingCubes:
      return "mc";
  }
  return "?";
}

}  // namespace isopatch
