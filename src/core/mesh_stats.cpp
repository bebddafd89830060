// Every statistic by a stable name (mesh_stats.hpp).
#include <isopatch/mesh_stats.hpp>

#include <string>

namespace isopatch {

void StageTimes::add(std::string_view stage, double s) {
  for (auto& [name, total] : seconds)
    if (name == stage) {
      total += s;
      return;
    }
  seconds.emplace_back(std::string(stage), s);
}

void StageTimes::merge(const StageTimes& other) {
  for (const auto& [name, s] : other.seconds) add(name, s);
}

double StageTimes::of(std::string_view stage) const {
  for (const auto& [name, total] : seconds)
    if (name == stage) return total;
  return 0.0;
}

void visit_stats(
    const MeshStats& stats,
    const std::function<void(std::string_view stage, std::string_view name, double value)>& visit) {
  const auto count = [](auto n) { return static_cast<double>(n); };
  visit("mesh", "seconds", stats.seconds);
  visit("mesh", "value_evaluations", count(stats.value_evaluations));
  visit("mesh", "gradient_evaluations", count(stats.gradient_evaluations));
  const double per_vertex = stats.vertices > 0 ? 1.0 / count(stats.vertices) : 0.0;
  visit("mesh", "value_evaluations_per_vertex", count(stats.value_evaluations) * per_vertex);
  visit("mesh", "gradient_evaluations_per_vertex", count(stats.gradient_evaluations) * per_vertex);
  visit("mesh", "threads", stats.threads);
  visit("mesh", "vertices", count(stats.vertices));
  visit("mesh", "triangles", count(stats.triangles));
  for (const auto& [stage, seconds] : stats.times.seconds) visit("seconds", stage, seconds);
  if (const auto& p = stats.projection) {
    const auto v = [&](std::string_view name, double value) { visit("projection", name, value); };
    v("depth", p->start_depth);
    v("max_depth", p->depth_limit);
    v("resolution", p->resolution);
    v("side_segments_min", p->side_segments_min);
    v("side_segments_max", p->side_segments_max);
    for (const auto& [n, patches] : p->patches_by_sides) v("patches_" + std::to_string(n), count(patches));
    v("rejected_patches", count(p->rejected_patches));
    v("rejected_sides", count(p->rejected_sides));
    v("refined_patches", count(p->refined_patches));
    v("fallback_cells", count(p->fallback_cells));
    v("unprojected", count(p->unprojected_vertices));
    v("gradient_rays", count(p->gradient_rays));
    v("clamped_base_points", count(p->clamped_base_points));
    v("refinements", count(p->refinements));
    v("curvature_depth_steps", count(p->curvature_depth_steps));
    v("flat_corner_leaves", count(p->flat_corner_cells));
    for (const auto& [depth, cells] : p->cells_by_depth)
      v("leaves_depth_" + std::to_string(depth), count(cells));
    v("base_coons", p->coons_base ? 1.0 : 0.0);
    if (const auto& d = p->defects) {
      for (int k = 0; k < RawDefects::kKinds; ++k) {
        const std::string kind = std::string("defect_") + RawDefects::kNames[k] + "_";
        v(kind + "vertices", count(d->vertices[k]));
        v(kind + "irregular", count(d->irregular_vertices[k]));
        v(kind + "triangles", count(d->triangles[k]));
        v(kind + "under_20", count(d->triangles_under_20[k]));
        v(kind + "under_10", count(d->triangles_under_10[k]));
      }
      v("defect_short_edges", count(d->short_edges));
    }
  }
  if (const auto& m = stats.marching_cubes) {
    visit("marching_cubes", "cells", count(m->cells));
    visit("marching_cubes", "cell_size", m->cell_size);
  }
  if (const auto& f = stats.fairing) {
    visit("fairing", "fair_iterations", f->iterations);
    visit("fairing", "fair_unconverged", count(f->unconverged));
  }
  if (const auto& c = stats.cleanup) {
    const auto v = [&](std::string_view name, double value) { visit("cleanup", name, value); };
    v("remesh_iterations", c->iterations);
    v("remesh_splits", count(c->splits));
    v("remesh_collapses", count(c->collapses));
    v("remesh_flips", count(c->flips));
    v("remesh_repairs", count(c->repairs));
    v("remesh_rejected_moves", count(c->rejected_moves));
    v("remesh_exactness_moves", count(c->exactness_moves));
    v("hessian_evaluations", count(c->hessian_evaluations));
  }
  if (const auto& r = stats.refine) {
    const auto v = [&](std::string_view name, double value) { visit("refine", name, value); };
    v("level", r->level);
    v("first_level", r->first_level);
    v("attempts", r->attempts);
    v("target_edge", r->target_edge);
    v("largest_curvature", r->largest_curvature);
    v("estimated_curvature", r->estimated_curvature);
    v("base_vertices", count(r->base_vertices));
    v("base_triangles", count(r->base_triangles));
    v("failed_points", count(r->failed_points));
    v("rejected_moves", count(r->rejected_moves));
    v("angle_vertices", count(r->angle_vertices));
    v("repaired_vertices", count(r->repaired_vertices));
    v("smallest_angle", r->smallest_angle);
    v("gradient_evaluations", count(r->gradient_evaluations));
  }
  if (const auto& l = stats.local_sizes) {
    const auto v = [&](std::string_view name, double value) { visit("local_sizes", name, value); };
    v("sources", count(l->sources));
    v("curvature_sources", count(l->curvature_sources));
    v("around", count(l->around));
    v("smallest_size", l->smallest_size);
    v("added_vertices", count(l->added_vertices));
    for (int a = 0; a < 3; ++a) v(std::string("extent_lo_") + "xyz"[a], l -> extent.lo[a]);
    for (int a = 0; a < 3; ++a) v(std::string("extent_hi_") + "xyz"[a], l -> extent.hi[a]);
  }
  if (const auto& c = stats.creases) {
    const auto v = [&](std::string_view name, double value) { visit("creases", name, value); };
    v("faces", count(c->faces));
    v("creases", count(c->creases));
    v("corners", count(c->corners));
    v("seams", count(c->seams));
    v("pieces", count(c->pieces));
    v("smooth_pairs", count(c->smooth_pairs));
    v("repair_moves", count(c->repair_moves));
    v("interval_cells", count(c->interval_cells));
    v("interval_creases", count(c->interval_creases));
    v("uncertain_cells", count(c->uncertain_cells));
    v("caps", count(c->caps));
    v("crease_vertices", count(c->crease_vertices));
    v("cut_planes", count(c->cut_planes));
    v("seconds", c->seconds);
  }
  if (const auto& sheet = stats.sheet) visit("sheet", "walls", count(sheet->walls));
  const MeshWarnings& w = stats.warnings;
  const auto v = [&](std::string_view name, double value) { visit("warnings", name, value); };
  if (stats.creases) v("exempt_corners", count(w.exempt_corners));
  if (stats.creases) v("uncertain_crease_cells", count(w.uncertain_crease_cells));
  if (w.creases_leave_box > 0) v("creases_leave_box", count(w.creases_leave_box));
  if (w.creases_in_partition > 0) v("creases_in_partition", count(w.creases_in_partition));
  if (w.creases_rounded > 0) v("creases_rounded", count(w.creases_rounded));
  if (w.creases_finer_edge > 0.0) v("creases_finer_edge", w.creases_finer_edge);
  if (w.self_intersecting_pairs > 0) {
    v("self_intersecting_pairs", count(w.self_intersecting_pairs));
    for (int a = 0; a < 3; ++a)
      v(std::string("self_intersection_near_") + "xyz"[a], w.self_intersection_near[a]);
  }
  if (stats.projection) {
    v("doubtful_cells", count(w.doubtful_cells));
    v("doubtful_topology_cells", count(w.doubtful_topology_cells));
    v("doubtful_grazing_faces", count(w.doubtful_grazing_faces));
    v("doubtful_cell_size", w.doubtful_cell_size);
    for (const auto& [reason, cells] : w.doubtful_cells_by_reason) v("doubtful_" + reason, count(cells));
  }
  if (w.error_bound_violations) v("error_bound_violations", count(*w.error_bound_violations));
  if (w.fan_patches > 0) {
    v("fan_patches", count(w.fan_patches));
    v("unprojected_fan_centres", count(w.unprojected_fan_centres));
  }
}

}  // namespace isopatch
