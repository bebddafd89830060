// validate() of every stage's settings (stage_settings.hpp, settings.hpp): one place per field, each
// error naming the field it is about.
#include <isopatch/error.hpp>
#include <isopatch/settings.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace isopatch {
namespace {

bool positive(const std::optional<double>& x) {
  return !x || (std::isfinite(*x) && *x > 0.0);
}

void check_count(const char* setting, const char* what, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw SettingError(setting, std::string(what) + " must be between " + std::to_string(lo) + " and " +
                                    std::to_string(hi) + ", got " + std::to_string(value));
}

bool open_angle(double degrees) {
  return degrees > 0.0 && degrees < 90.0;
}

}  // namespace

void SizeSettings::validate() const {
  if (!positive(edge_length)) throw SettingError("edge_length", "the edge length must be a positive number");
  if (!positive(max_error)) throw SettingError("max_error", "the maximum error must be a positive number");
  if (!positive(smallest_size))
    throw SettingError("smallest_size", "the smallest size must be a positive number");
  if (refine_around_depth < 0 || refine_around_depth > 6)
    throw SettingError("refine_around_depth", "the depth of refinement around points must be 0..6");
  for (const Vec3& p : refine_around)
    if (!p.allFinite()) throw SettingError("refine_around", "a point to refine around is not finite");
}

const Box& valid_box(const Box& box) {
  if (!box.valid()) throw SettingError("box", "the box must be finite with lo < hi on every axis");
  return box;
}

TargetSizes target_sizes(const SizeSettings& s, const Box& box) {
  TargetSizes sizes;
  sizes.largest = default_edge_length(s, box);
  sizes.smallest = std::min(sizes.largest, box.size().maxCoeff() / 2048.0);
  if (s.smallest_size) sizes.smallest = std::min(sizes.smallest, *s.smallest_size);
  sizes.max_error = s.max_error;
  sizes.user = s.size_field;
  return sizes;
}

void OctreeSettings::validate() const {
  if (min_depth < 0 || max_depth > kOctreeDepthLimit || min_depth > max_depth)
    throw SettingError(
        min_depth < 0 || min_depth > max_depth ? "min_depth" : "max_depth",
        "the depths must satisfy 0 <= min_depth <= max_depth <= " + std::to_string(kOctreeDepthLimit) +
            ", got " + std::to_string(min_depth) + " and " + std::to_string(max_depth));
  if (!(std::isfinite(max_cell_curvature) && max_cell_curvature >= 0.0))
    throw SettingError("max_cell_curvature",
                       "the largest cell curvature must be a finite number >= 0 (0: off)");
  check_count("refinement_levels", "the refinement levels", refinement_levels, 0, kOctreeDepthLimit);
}

void PatchSettings::validate() const {
  if (resolution != 0 && (resolution < 1 || resolution > kMaxPatchResolution))
    throw SettingError("resolution", "the resolution must be 0 (automatic) or between 1 and " +
                                         std::to_string(kMaxPatchResolution) + ", got " +
                                         std::to_string(resolution));
}

void ProjectionSettings::validate() const {
  if (!open_angle(max_ray_angle))
    throw SettingError("max_ray_angle", "the acceptance angle must lie strictly between 0 and 90 degrees");
  if (!open_angle(max_boundary_ray_angle))
    throw SettingError("max_boundary_ray_angle",
                       "the boundary acceptance angle must lie strictly between 0 and 90 degrees");
  check_count("march_steps", "the march steps", march_steps, 4, 4096);
}

void MarchingCubesSettings::validate() const {
  check_count("grid", "the marching cubes grid", grid, 1, 4096);
  if (!(grid_offset >= 0.0 && grid_offset < 1.0))
    throw SettingError("grid_offset", "the grid offset must be in [0, 1)");
  check_count("fair_iterations", "the fairing iterations", fair_iterations, 0, 10000);
}

void CleanupSettings::validate() const {
  if (remesh_iterations)
    check_count("remesh_iterations", "the remesh iterations", *remesh_iterations, 0, 100);
  check_count("valence_search", "the valence search (flips per chain)", valence_search, 0, kMaxValenceSearch);
  check_count("curvature_sweeps", "the curvature sweeps", curvature_sweeps, 0, kMaxCurvatureSweeps);
}

void BudgetSettings::validate() const {
  if (!(std::isfinite(time_limit) && time_limit >= 0.0))
    throw SettingError("time_limit", "the time limit must be a number of seconds >= 0");
  check_count("threads", "the thread count (0: every core)", threads, 0, kMaxThreads);
}

void BudgetSettings::check_cancel() const {
  if (cancel && cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled", "cancel");
}

void BudgetSettings::check_vertices(std::size_t vertices) const {
  if (max_vertices > 0 && vertices > max_vertices)
    throw LimitError("the mesh would exceed the vertex budget of " + std::to_string(max_vertices),
                     "max_vertices");
}

void RefineSettings::validate() const {
  if (refine < 0 || refine > kMaxRefineLevel)
    throw SettingError("refine", "must be 0.." + std::to_string(kMaxRefineLevel) + " (0: automatic, 1: off)");
}

Creases parse_creases(const std::string& name) {
  if (name == "auto") return Creases::Automatic;
  if (name == "off") return Creases::Off;
  if (name == "exact") return Creases::Exact;
  throw SettingError("creases", "unknown creases '" + name + "' (want auto, off or exact)");
}

void Settings::validate() const {
  SizeSettings::validate();
  OctreeSettings::validate();
  RefineSettings::validate();
  PatchSettings::validate();
  ProjectionSettings::validate();
  MarchingCubesSettings::validate();
  CleanupSettings::validate();
  BudgetSettings::validate();
  if (box) valid_box(*box);
  validate_region(region, "region");
  if (cells.size() > kMaxGivenCells)
    throw SettingError(
        "cells", "at most " + std::to_string(kMaxGivenCells) + " cells, got " + std::to_string(cells.size()));
  for (const ConvexRegion& cell : cells) validate_region(cell, "cells");
  if (frame &&
      !(std::isfinite(frame->azimuth) && std::isfinite(frame->elevation) && std::isfinite(frame->roll)))
    throw SettingError("frame", "the frame's angles must be finite numbers");
  const bool convex = !region.empty() || !cells.empty() || frame.has_value();
  if (convex && method != Method::Projection)
    throw SettingError("method", "a region, a frame or given cells need the projection method");
  if (!region.empty() && !cells.empty())
    throw SettingError("cells", "given cells and a region do not go together (clip the cells instead)");
}

Quality parse_quality(const std::string& name) {
  if (name == "preview") return Quality::Preview;
  if (name == "default") return Quality::Default;
  if (name == "fine") return Quality::Fine;
  throw SettingError("quality", "unknown quality '" + name + "' (want preview, default or fine)");
}

const char* quality_name(Quality quality) {
  switch (quality) {
    case Quality::Preview:
      return "preview";
    case Quality::Default:
      return "default";
    case Quality::Fine:
      return "fine";
  }
  return "?";
}

}  // namespace isopatch
