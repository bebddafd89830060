// `isopatch analyze`: MESH [+ SURFACE] -> analyze_quality -> a readable report or JSON, and optionally
// the per-vertex curvature and distance fields written as PLY attributes.
#include <isopatch/curvature.hpp>
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "commands.hpp"
#include "singular_report.hpp"

namespace isopatch::cli {
namespace {

using nlohmann::json;

/// The element shape is also measured outside balls of this many mean edge lengths about the singular
/// points of f = 0.
constexpr double kSingularBallEdges = 2.0;

struct AnalyzeOptions {
  std::string mesh;
  std::string surface;
  std::string box;
  std::vector<std::string> params;
  std::string write;
  bool json = false;
};

// ---- JSON -----------------------------------------------------------------------------------------
// nlohmann writes NaN and infinities as null, which is what an undefined statistic should read as.

json to_json(const Distribution& d) {
  return {{"count", d.count}, {"min", d.min}, {"p1", d.p1},   {"p5", d.p5},     {"median", d.median},
          {"p95", d.p95},     {"p99", d.p99}, {"max", d.max}, {"mean", d.mean}, {"rms", d.rms}};
}

json to_json(const TopologyReport& t) {
  json j = {{"vertices", t.vertices},
            {"edges", t.edges},
            {"triangles", t.triangles},
            {"components", t.components.size()},
            {"boundary_edges", t.boundary_edges},
            {"non_manifold_edges", t.non_manifold_edges},
            {"non_manifold_vertices", t.non_manifold_vertices},
            {"inconsistent_edges", t.inconsistent_edges},
            {"degenerate_triangles", t.degenerate_triangles},
            {"unreferenced_vertices", t.unreferenced_vertices},
            {"duplicate_vertices", t.duplicate_vertices},
            {"euler_characteristic", t.euler_characteristic},
            {"genus", t.genus},
            {"watertight", t.watertight()},
            {"manifold", t.manifold()},
            {"consistently_oriented", t.consistently_oriented()},
            {"outward_oriented", t.outward_oriented()}};
  return j;
}

json to_json(const ShapeReport& s) {
  return {{"min_angle_degrees", to_json(s.min_angle)},  {"share_below_10_degrees", s.share_below_10},
          {"share_below_20_degrees", s.share_below_20}, {"share_below_30_degrees", s.share_below_30},
          {"aspect_ratio", to_json(s.aspect_ratio)},    {"quality", to_json(s.quality)},
          {"edge_length", to_json(s.edge_length)},      {"edge_length_cv", s.edge_length_cv}};
}

json to_json(const ValenceReport& v) {
  return {{"interior_vertices", v.interior_vertices},
          {"other_vertices", v.other_vertices},
          {"histogram", v.histogram},
          {"share_6", v.share_6},
          {"share_5_to_7", v.share_5_to_7}};
}

json to_json(const CurvatureError& c) {
  return {{"vertices", c.vertices},
          {"undefined", c.undefined},
          {"nrms", c.nrms},
          {"abs_error", to_json(c.abs_error)}};
}

json to_json(const AccuracyReport& a) {
  return {{"diagonal", a.diagonal},
          {"vertex_distance", to_json(a.vertex_distance)},
          {"centroid_distance", to_json(a.centroid_distance)},
          {"vertex_distance_relative",
           {{"max", a.vertex_distance.max / a.diagonal}, {"rms", a.vertex_distance.rms / a.diagonal}}},
          {"centroid_distance_relative",
           {{"max", a.centroid_distance.max / a.diagonal}, {"rms", a.centroid_distance.rms / a.diagonal}}},
          {"triangle_normal_error_degrees", to_json(a.triangle_normal_error)},
          {"vertex_normal_error_degrees", to_json(a.vertex_normal_error)},
          {"undefined_samples", a.undefined_samples},
          {"mean_curvature", to_json(a.mean_curvature)},
          {"gaussian_curvature", to_json(a.gaussian_curvature)}};
}

json to_json(const SelfIntersectionReport& r) {
  json j = {{"pairs", r.pairs}, {"capped", r.capped}};
  if (r.pairs > 0) {
    j["example_triangles"] = {r.example[0], r.example[1]};
    j["example_point"] = {r.example_point.x(), r.example_point.y(), r.example_point.z()};
  }
  return j;
}

json to_json(const ShapeAwayReport& a) {
  return {{"radius", a.radius},
          {"radius_in_mean_edge_lengths", kSingularBallEdges},
          {"balls", a.centres},
          {"triangles", a.triangles},
          {"triangles_left_out", a.triangles_near},
          {"min_angle_degrees", a.triangles > 0 ? json(a.smallest_angle) : json(nullptr)},
          {"share_below_20_degrees", a.share_below_20},
          {"interior_vertices", a.interior_vertices},
          {"valence_share_6", a.share_6}};
}

// ---- text -----------------------------------------------------------------------------------------

std::string yes_no(bool b) {
  return b ? "yes" : "no";
}

void print_topology(const TopologyReport& t) {
  std::printf("topology   %zu component%s, genus %d, Euler characteristic %ld\n", t.components.size(),
              t.components.size() == 1 ? "" : "s", t.genus, t.euler_characteristic);
  std::printf("           watertight %s, manifold %s, consistently oriented %s, outward %s\n",
              yes_no(t.watertight()).c_str(), yes_no(t.manifold()).c_str(),
              yes_no(t.consistently_oriented()).c_str(), yes_no(t.outward_oriented()).c_str());
  if (t.boundary_edges + t.non_manifold_edges + t.non_manifold_vertices + t.degenerate_triangles +
          t.duplicate_vertices + t.unreferenced_vertices >
      0)
    std::printf(
        "           boundary edges %zu, non-manifold edges %zu / vertices %zu, degenerate triangles %zu, "
        "duplicate vertices %zu, unreferenced %zu\n",
        t.boundary_edges, t.non_manifold_edges, t.non_manifold_vertices, t.degenerate_triangles,
        t.duplicate_vertices, t.unreferenced_vertices);
}

void print_self_intersections(const SelfIntersectionReport& r) {
  if (r.pairs == 0) {
    std::printf("           self-intersections none\n");
    return;
  }
  std::printf(
      "           self-intersections %s%zu pairs of triangles (e.g. %zu and %zu at %.6g, %.6g, %.6g)\n",
      r.capped ? "at least " : "", r.pairs, r.example[0], r.example[1], r.example_point.x(),
      r.example_point.y(), r.example_point.z());
}

void print_shape(const ShapeReport& s) {
  const Distribution& a = s.min_angle;
  std::printf("min angle  min %.2f, p1 %.2f, p5 %.2f, median %.2f degrees\n", a.min, a.p1, a.p5, a.median);
  std::printf("           under 10/20/30 degrees: %.2f%% / %.2f%% / %.2f%% of triangles\n",
              100.0 * s.share_below_10, 100.0 * s.share_below_20, 100.0 * s.share_below_30);
  std::printf("aspect     R/2r median %.3f, p95 %.3f, max %.3g\n", s.aspect_ratio.median, s.aspect_ratio.p95,
              s.aspect_ratio.max);
  std::printf("quality    Q min %.3f, p5 %.3f, median %.3f\n", s.quality.min, s.quality.p5, s.quality.median);
  std::printf("edges      length mean %.4g, min %.4g, max %.4g, cv %.3f\n", s.edge_length.mean,
              s.edge_length.min, s.edge_length.max, s.edge_length_cv);
}

void print_valence(const ValenceReport& v) {
  std::printf("valence    %s interior vertices (%s others): %.2f%% of valence 6, %.2f%% of 5..7\n",
              group_digits(v.interior_vertices).c_str(), group_digits(v.other_vertices).c_str(),
              100.0 * v.share_6, 100.0 * v.share_5_to_7);
  std::string histogram;
  for (std::size_t k = 0; k < v.histogram.size(); ++k)
    if (v.histogram[k] > 0) histogram += " " + std::to_string(k) + ":" + group_digits(v.histogram[k]);
  if (!histogram.empty()) std::printf("           histogram%s\n", histogram.c_str());
}

void print_curvature(const char* label, const CurvatureError& c) {
  std::printf("%-10s nRMS %.4g, |error| median %.3g, p95 %.3g, max %.3g (%zu vertices", label, c.nrms,
              c.abs_error.median, c.abs_error.p95, c.abs_error.max, c.vertices);
  if (c.undefined > 0) std::printf(", %zu undefined", c.undefined);
  std::printf(")\n");
}

void print_accuracy(const std::string& surface, const AccuracyReport& a) {
  std::printf("surface    %s (bounding-box diagonal %.4g)\n", surface.c_str(), a.diagonal);
  std::printf("distance   vertices  max %.3e, rms %.3e (relative %.3e, %.3e)\n", a.vertex_distance.max,
              a.vertex_distance.rms, a.vertex_distance.max / a.diagonal, a.vertex_distance.rms / a.diagonal);
  std::printf("           centroids max %.3e, rms %.3e (relative %.3e, %.3e)\n", a.centroid_distance.max,
              a.centroid_distance.rms, a.centroid_distance.max / a.diagonal,
              a.centroid_distance.rms / a.diagonal);
  std::printf("normals    triangles mean %.3f, p95 %.3f, max %.3f degrees\n", a.triangle_normal_error.mean,
              a.triangle_normal_error.p95, a.triangle_normal_error.max);
  std::printf("           vertices  mean %.3f, p95 %.3f, max %.3f degrees\n", a.vertex_normal_error.mean,
              a.vertex_normal_error.p95, a.vertex_normal_error.max);
  if (a.undefined_samples > 0)
    std::printf("           %zu samples undefined (grad f = 0, f not finite, or zero normal)\n",
                a.undefined_samples);
  print_curvature("H", a.mean_curvature);
  print_curvature("K", a.gaussian_curvature);
}

/// The singular points found and the element shape away from them.
void print_singular(const SingularRun& run, const std::optional<ShapeAwayReport>& away) {
  const SingularPoints& f = run.found;
  if (f.isolated_points() + f.curves() > 0) {
    std::printf("singular   %s\n", describe_singular_points(f, run.box).c_str());
  } else if (f.status == SingularSearchStatus::BudgetExhausted) {
    std::printf("singular   none found; the search stopped at its budget (%s)\n", f.reason.c_str());
  }
  if (!away) return;
  std::printf(
      "away       outside balls of radius %.4g (%g mean edge lengths) about them: %s of %s triangles\n",
      away->radius, kSingularBallEdges, group_digits(away->triangles).c_str(),
      group_digits(away->triangles + away->triangles_near).c_str());
  std::printf(
      "           min angle %.2f degrees, %.2f%% under 20 degrees; %.2f%% of valence 6 (%s interior "
      "vertices)\n",
      away->smallest_angle, 100.0 * away->share_below_20, 100.0 * away->share_6,
      group_digits(away->interior_vertices).c_str());
}

bool has_ply_extension(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".ply";
}

int run_analyze(const AnalyzeOptions& o) {
  if (o.surface.empty()) {
    if (!o.write.empty()) throw InputError("--write needs --surface (the fields compare the mesh with f)");
    if (!o.box.empty() || !o.params.empty()) throw InputError("--box and --param need --surface");
  }
  if (!o.write.empty()) {
    if (!has_ply_extension(o.write))
      throw InputError("--write '" + o.write + "': the fields are vertex attributes, which only PLY stores");
    check_output_path(o.write);
  }
  Mesh mesh = read_mesh(o.mesh);
  SurfacePtr surface;
  if (!o.surface.empty()) surface = resolve_surface_for_mesh(o.surface, o.box, o.params, mesh);

  const QualityReport report = analyze_quality(mesh, surface.get());
  // Singular points of f = 0, and the element shape outside balls about them (where the surface itself
  // is not smooth, no mesh is well shaped).
  std::optional<SingularRun> singular;
  std::optional<ShapeAwayReport> away;
  if (surface && mesh.triangle_count() > 0) {
    const double edge = report.shape.edge_length.mean;
    singular = search_singular_points(*surface, surface->box(), edge);
    const std::vector<Vec3> centres = singular->found.singular_samples();
    if (!centres.empty()) away = analyze_shape_away(mesh, centres, kSingularBallEdges * edge);
  }

  if (o.json) {
    json j = {
        {"mesh", {{"file", o.mesh}, {"vertices", mesh.vertex_count()}, {"triangles", mesh.triangle_count()}}},
        {"topology", to_json(report.topology)},
        {"self_intersections", to_json(report.self_intersections)},
        {"shape", to_json(report.shape)},
        {"valence", to_json(report.valence)}};
    if (report.accuracy) {
      j["accuracy"] = to_json(*report.accuracy);
      j["accuracy"]["surface"] = surface->name();
    }
    if (singular) j["singular_points"] = singular_json(*singular);
    if (away) j["away_from_singular_points"] = to_json(*away);
    std::cout << j.dump(2) << "\n";
  } else {
    std::printf("mesh       %s: %s vertices, %s triangles\n", o.mesh.c_str(),
                group_digits(mesh.vertex_count()).c_str(), group_digits(mesh.triangle_count()).c_str());
    print_topology(report.topology);
    print_self_intersections(report.self_intersections);
    print_shape(report.shape);
    print_valence(report.valence);
    if (report.accuracy) print_accuracy(surface->name(), *report.accuracy);
    if (singular) print_singular(*singular, away);
  }

  if (!o.write.empty()) {
    attach_fields(mesh, *surface);
    write_mesh(mesh, o.write);
    if (!o.json) std::printf("wrote      %s\n", o.write.c_str());
  }
  return 0;
}

}  // namespace

Runner add_analyze_command(CLI::App& app) {
  auto o = std::make_shared<AnalyzeOptions>();
  CLI::App* cmd =
      app.add_subcommand("analyze", "Measure a mesh: topology, element shape, valence, accuracy against f");
  cmd->add_option("mesh", o->mesh, "Mesh file: .ply, .obj, .off or .stl")->required();
  cmd->add_option("--surface", o->surface,
                  "The surface it approximates: catalogue name, formula, @file or a composite (.ipatch)");
  cmd->add_option("--box", o->box,
                  "Box x0,y0,z0,x1,y1,z1 for a formula surface (default: the mesh's bounds)");
  cmd->add_option("--param", o->params, "Override a definition of the formula: name=value (repeatable)");
  cmd->add_flag("--json", o->json, "Print the report as JSON");
  cmd->add_option("--write", o->write,
                  "Write the mesh with per-vertex fields to this .ply (needs --surface): mean_curvature, "
                  "mean_curvature_exact, gaussian_curvature, gaussian_curvature_exact, distance");
  return [o] { return run_analyze(*o); };
}

}  // namespace isopatch::cli
