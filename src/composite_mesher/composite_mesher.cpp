/// \file composite_mesher.cpp
/// A composite meshed by projection with shared curve samples (composite_mesher.hpp).
#include "composite_mesher/composite_mesher.hpp"

#include <isopatch/remesh.hpp>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include "composite_mesher/composite_assembly.hpp"
#include "composite_mesher/composite_curves.hpp"
#include "composite_mesher/composite_rounds.hpp"
#include "composite_model/composite_checks.hpp"
#include "surface/sampler.hpp"
#include "surface/target_size.hpp"

namespace isopatch {

namespace {

/// How far outside a bound of its region (in the first-order distance b / |grad b|) an interior vertex
/// may land, as a share of the edge length: the bounds are the patches' own seams, which the vertices
/// beside a curve approach to within a fraction of an edge.
constexpr double kRegionTolerance = 0.05;

}  // namespace

CompositeMesh mesh_composite_projection(const Composite& c, const Settings& settings, MeshStats* stats) {
  settings.validate();
  check_composite(c);
  const auto start = std::chrono::steady_clock::now();
  const Box box = settings.box.value_or(c.box);
  const TargetSizes sizes = target_sizes(settings, valid_box(box));
  std::vector<std::unique_ptr<Sampler>> samplers;
  for (const CompositePatch& p : c.patches) samplers.push_back(std::make_unique<Sampler>(*p.surface));

  CurvePlan curves = plan_curves(c, sizes, settings.resolution);
  std::vector<int>& segments = curves.segments;

  CompositePatchParams params;
  params.coordinates = settings.coordinates == Settings::Coordinates::MeanValue ? CoordinateKind::MeanValue
                                                                                : CoordinateKind::Wachspress;
  params.projection = projection_params(settings, settings.resolution);
  // The construction knows the curves: the Coons patch over them unless another base is asked for.
  params.base = settings.base == Settings::Base::Automatic ? Settings::Base::Coons : settings.base;
  params.region_tolerance = kRegionTolerance * sizes.largest;

  ProjectionStats ps;
  ps.resolution = settings.resolution;
  ps.coons_base = params.base == Settings::Base::Coons;
  ProjectedPatches patches = project_patches(c, samplers, curves, params, settings, ps);

  const auto projected = std::chrono::steady_clock::now();
  const int iterations = settings.remesh_iterations.value_or(kDefaultRemeshIterations);
  const std::vector<RemeshStats> cleanup = clean_up_patches(c, patches, settings, sizes, iterations);
  CompositeMesh out = assemble_composite(c, patches, segments, settings, iterations > 0, ps);
  if (stats) {
    const auto [lo, hi] = std::minmax_element(segments.begin(), segments.end());
    ps.side_segments_min = segments.empty() ? 0 : *lo;
    ps.side_segments_max = segments.empty() ? 0 : *hi;
    stats->projection = ps;
    stats->warnings.fan_patches = ps.fallback_cells;
    stats->warnings.unprojected_fan_centres = ps.unprojected_vertices;
    for (const auto& s : samplers) {
      stats->value_evaluations += s->value_count();
      stats->gradient_evaluations += s->gradient_count();
    }
    if (iterations > 0) {
      RemeshStats total;
      for (const RemeshStats& r : cleanup) total.add_counts(r);
      stats->gradient_evaluations += total.gradient_evaluations;
      stats->cleanup = total;
      if (settings.max_error) stats->warnings.error_bound_violations = total.error_bound_violations;
    }
    stats->vertices = out.mesh.vertex_count();
    stats->triangles = out.mesh.triangle_count();
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->times.add("patches", std::chrono::duration<double>(projected - start).count());
    if (iterations > 0)
      stats->times.add("cleanup",
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - projected).count());
  }
  return out;
}

}  // namespace isopatch
