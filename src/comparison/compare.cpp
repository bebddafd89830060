// Meshers side by side at matched vertex counts (see include/isopatch/compare.hpp).
#include <isopatch/compare.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace isopatch {
namespace {

ComparisonRow measure(const Surface& surface, std::string method, int level, Mesh mesh,
                      const MeshStats& stats) {
  const QualityReport q = analyze_quality(mesh, &surface);
  ComparisonRow row;
  row.method = std::move(method);
  row.level = level;
  row.vertices = mesh.vertex_count();
  row.seconds = stats.seconds;
  row.evaluations = stats.value_evaluations + stats.gradient_evaluations;
  row.valence6 = q.valence.share_6;
  row.min_angle = q.shape.min_angle.min;
  row.share_below_20 = q.shape.share_below_20;
  row.normal_error = q.accuracy->vertex_normal_error.mean;
  row.h_nrms = q.accuracy->mean_curvature.nrms;
  row.mesh = std::move(mesh);
  return row;
}

/// Marching cubes with the grid whose vertex count is closest to `target` (vertex counts grow about
/// quadratically with the grid; two corrections suffice).
Mesh matched_marching_cubes(const Surface& surface, Settings settings, std::size_t target, MeshStats& stats) {
  settings.method = Method::MarchingCubes;
  settings.grid = 32;
  Mesh mesh = mesh_surface(surface, settings, &stats);
  for (int round = 0; round < 3 && mesh.vertex_count() > 0; ++round) {
    const double ratio = static_cast<double>(target) / static_cast<double>(mesh.vertex_count());
    const int grid = std::clamp(static_cast<int>(std::lround(settings.grid * std::sqrt(ratio))), 2, 1024);
    if (grid == settings.grid) break;
    settings.grid = grid;
    mesh = mesh_surface(surface, settings, &stats);
  }
  return mesh;
}

/// The comparison with `project(settings, stats)` making the projection meshes.
template <class Project>
std::vector<ComparisonRow> compare_with(const Surface& surface, const ComparisonSettings& settings,
                                        Project&& project) {
  std::vector<double> edges = settings.edge_lengths;
  const Box box = settings.base.box.value_or(surface.box());
  if (edges.empty())
    for (double divisions : {24.0, 40.0, 64.0}) edges.push_back(box.size().maxCoeff() / divisions);
  std::vector<ComparisonRow> rows;
  for (std::size_t level = 0; level < edges.size(); ++level) {
    Settings projection = settings.base;
    projection.method = Method::Projection;
    projection.edge_length = edges[level];
    MeshStats p_stats;
    Mesh p_mesh = project(projection, p_stats);
    const std::size_t target = p_mesh.vertex_count();

    MeshStats mc_stats;
    Mesh mc_mesh = matched_marching_cubes(surface, settings.base, target, mc_stats);
    Mesh faired = mc_mesh;
    MeshStats fair_stats = mc_stats;
    const auto start = std::chrono::steady_clock::now();
    const FairingStats fairing = laplace_fair(faired, surface, settings.fair_iterations);
    fair_stats.gradient_evaluations += fairing.gradient_evaluations;
    fair_stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const int l = static_cast<int>(level);
    rows.push_back(measure(surface, "mc", l, std::move(mc_mesh), mc_stats));
    rows.push_back(measure(surface, "mc+fair", l, std::move(faired), fair_stats));
    rows.push_back(measure(surface, "projection", l, std::move(p_mesh), p_stats));
  }
  return rows;
}

}  // namespace

std::vector<ComparisonRow> compare_methods(const Surface& surface, const ComparisonSettings& settings) {
  return compare_with(surface, settings,
                      [&](const Settings& s, MeshStats& stats) { return mesh_surface(surface, s, &stats); });
}

std::vector<ComparisonRow> compare_methods(const CompositeModel& model, const ComparisonSettings& settings) {
  return compare_with(*model.surface(), settings,
                      [&](const Settings& s, MeshStats& stats) { return mesh_composite(model, s, &stats); });
}

}  // namespace isopatch
