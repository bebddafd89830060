// Singular points as the tool reports them (singular_report.hpp).
#include "singular_report.hpp"

#include <isopatch/isopatch.hpp>
#include <isopatch/stage_settings.hpp>

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>
#include <string>

namespace isopatch::cli {
namespace {

nlohmann::ordered_json point_json(const Vec3& p) {
  return nlohmann::ordered_json::array({p.x(), p.y(), p.z()});
}

/// The bounds, in the user's coordinates, of `box` seen in the frame R (x_user = R y).
Box rotated_bounds(const Box& box, const Mat3& r) {
  Box out{Vec3::Constant(std::numeric_limits<double>::infinity()),
          Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c((corner & 1) ? box.hi.x() : box.lo.x(), (corner & 2) ? box.hi.y() : box.lo.y(),
                 (corner & 4) ? box.hi.z() : box.lo.z());
    const Vec3 p = r * c;
    out.lo = out.lo.cwiseMin(p);
    out.hi = out.hi.cwiseMax(p);
  }
  return out;
}

}  // namespace

SingularRun search_singular_points(const Surface& surface, const Box& box, double edge_length,
                                   const ConvexRegion& region, const std::optional<Frame>& frame,
                                   bool sampled) {
  SingularRun run;
  const Mat3 r = frame ? frame->rotation() : Mat3::Identity();
  run.box = frame ? rotated_bounds(box, r) : box;
  SingularSearchSettings s;
  // A sampled surface's bounds reach a few samples around a box (its spline's support), so near a narrow
  // band's clamped values they never exclude grad f = 0: boxes of two edge lengths, not a quarter of one,
  // keep its search to a few thousand starts (a singular point smaller than two edges is noise of the
  // samples).
  s.min_box_size = std::max((sampled ? 2.0 : 0.25) * edge_length, box.size().maxCoeff() / 1024.0);
  const double margin = 1e-9 * box.diagonal();
  const double face = 1e-6 * box.size().maxCoeff();
  if (frame || !region.empty() || sampled)
    s.inside = [&](const Vec3& p) {
      const Vec3 q = r.transpose() * p;  // in the frame's coordinates
      if (frame && !box.contains(q, margin)) return false;
      if (sampled && !box.contains(q, -face)) return false;
      return std::all_of(region.begin(), region.end(), [&](const HalfSpace& h) {
        const double scale = Vec3(h.a, h.b, h.c).norm();
        return h.a * q.x() + h.b * q.y() + h.c * q.z() + h.d <= margin * scale;
      });
    };
  const auto t0 = std::chrono::steady_clock::now();
  run.found = find_shape_singular_points(surface, run.box, s);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return run;
}

SingularRun search_singular_points(const Surface& surface, const Settings& settings, bool sampled) {
  const Box box = settings.box.value_or(surface.box());
  return search_singular_points(surface, box, default_edge_length(settings, box), settings.region,
                                settings.frame, sampled);
}

void print_singular_warning(const SingularRun& run, std::FILE* out) {
  const SingularPoints& f = run.found;
  if (!f.components.empty()) {
    std::fprintf(out, "warning: %s\n", describe_singular_points(f, run.box).c_str());
  } else if (f.status == SingularSearchStatus::BudgetExhausted) {
    std::fprintf(out,
                 "warning: the search for singular points of f = 0 (grad f = 0) stopped at its budget (%s) "
                 "and found none in what it covered\n",
                 f.reason.c_str());
  }
}

nlohmann::ordered_json singular_json(const SingularRun& run) {
  const SingularPoints& f = run.found;
  nlohmann::ordered_json j = {{"status", status_name(f.status)},
                              {"searched", f.searched()},
                              {"complete", f.status == SingularSearchStatus::Complete}};
  if (!f.reason.empty()) j["reason"] = f.reason;
  j["points"] = f.isolated_points();
  j["curves"] = f.curves();
  j["degenerate"] = f.degenerate();
  nlohmann::ordered_json positions = nlohmann::ordered_json::array();
  nlohmann::ordered_json curves = nlohmann::ordered_json::array();
  nlohmann::ordered_json degenerate = nlohmann::ordered_json::array();
  std::size_t first = 0;  // the component's samples in f.points
  for (const SingularComponent& c : f.components) {
    nlohmann::ordered_json samples = nlohmann::ordered_json::array();
    for (std::size_t k = first; k < first + c.samples; ++k) samples.push_back(point_json(f.points[k]));
    first += c.samples;
    nlohmann::ordered_json entry = {{"samples", c.samples},
                                    {"from", point_json(c.extent.lo)},
                                    {"to", point_json(c.extent.hi)},
                                    {"points", std::move(samples)}};
    if (c.smooth_sheet)
      degenerate.push_back(std::move(entry));
    else if (c.curve)
      curves.push_back(std::move(entry));
    else
      positions.push_back(point_json(c.position));
  }
  j["positions"] = std::move(positions);
  j["curve_list"] = std::move(curves);
  j["degenerate_list"] = std::move(degenerate);
  j["box"] = {point_json(run.box.lo), point_json(run.box.hi)};
  j["min_box_size"] = f.min_box_size;
  j["spacing"] = f.spacing;
  j["boxes"] = f.boxes;
  j["starts"] = f.starts;
  j["seconds"] = run.seconds;
  return j;
}

}  // namespace isopatch::cli
