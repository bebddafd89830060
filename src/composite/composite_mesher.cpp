/// \file composite_mesher.cpp
/// A composite meshed by projection with shared curve samples (composite_mesher.hpp).
#include "composite/composite_mesher.hpp"

#include <isopatch/error.hpp>
#include <isopatch/remesh.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "composite/curve_samples.hpp"
#include "composite/patch_projection.hpp"
#include "composite/patch_relaxation.hpp"
#include "project/vertex_role.hpp"
#include "remesh/remesh_presets.hpp"
#include "surface/sampler.hpp"
#include "surface/target_size.hpp"

namespace isopatch {

namespace {

constexpr int kCoonsSegments = 128;  // the dense polyline of a curve for the Coons base
constexpr int kSizeSamples = 9;      // points of a curve where a varying target size is read

using Key = std::array<double, 3>;
Key key(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

/// The curves sampled at their segment counts, with mesh ids: the corners first (in the order the
/// curves meet them), then each curve's inner samples in curve order.
struct CurveSampling {
  std::vector<Vec3> positions;
  std::size_t corners = 0;                      // positions[0, corners) are the corners
  std::vector<std::vector<std::uint32_t>> ids;  // per curve, start to end
  std::vector<std::vector<Vec3>> points;        // per curve, start to end
};

/// Curves no patch uses get no vertices.
CurveSampling sample_curves(const Composite& c, const std::vector<int>& segments,
                            const std::vector<bool>& used) {
  CurveSampling s;
  std::map<Key, std::uint32_t> corner_of;
  const auto corner = [&](const Vec3& p) {
    const auto [it, fresh] = corner_of.emplace(key(p), static_cast<std::uint32_t>(s.positions.size()));
    if (fresh) s.positions.push_back(p);
    return it->second;
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends(c.curves.size());
  for (std::size_t i = 0; i < c.curves.size(); ++i)
    if (used[i]) ends[i] = {corner(c.curves[i].start), corner(c.curves[i].end)};
  s.corners = s.positions.size();
  s.ids.resize(c.curves.size());
  s.points.resize(c.curves.size());
  for (std::size_t i = 0; i < c.curves.size(); ++i) {
    if (!used[i]) continue;
    s.points[i] = sample_arc(c.curves[i], segments[i]);
    s.ids[i].push_back(ends[i].first);
    for (std::size_t j = 1; j + 1 < s.points[i].size(); ++j) {
      s.ids[i].push_back(static_cast<std::uint32_t>(s.positions.size()));
      s.positions.push_back(s.points[i][j]);
    }
    s.ids[i].push_back(ends[i].second);
  }
  return s;
}

PatchBoundary boundary_of(const CompositePatch& patch, const CurveSampling& s,
                          const std::vector<std::vector<Vec3>>& dense) {
  PatchBoundary b;
  for (const PatchSide& side : patch.sides) {
    auto points = s.points[side.curve];
    auto ids = s.ids[side.curve];
    auto line = dense[side.curve];
    if (side.reversed) {
      std::reverse(points.begin(), points.end());
      std::reverse(ids.begin(), ids.end());
      std::reverse(line.begin(), line.end());
    }
    b.points.push_back(std::move(points));
    b.ids.push_back(std::move(ids));
    b.dense.push_back(std::move(line));
  }
  return b;
}

/// The segments a patch asks of one of its curves: the curve's length over the target size there on the
/// patch's function (rounded, 1..kMaxPatchResolution), or the fixed resolution.
int curve_segment_count(const ConicArc& arc, const Surface& surface, const TargetSizes& sizes,
                        int resolution) {
  const double length = arc_length(arc);
  if (resolution > 0) return resolution;
  double h = sizes.largest;
  if (sizes.varies())
    for (int i = 0; i < kSizeSamples; ++i)
      h = std::min(h, target_size(surface, sizes, arc.point(static_cast<double>(i) / (kSizeSamples - 1))));
  const double count = std::round(length / h);
  return static_cast<int>(std::clamp(count, 1.0, static_cast<double>(kMaxPatchResolution)));
}

/// The per-patch clean-up's settings: the preset's passes (remesh_presets.hpp) with these sizes.
RemeshSettings cleanup_settings(const Settings& s, const TargetSizes& sizes, int iterations) {
  RemeshSettings r = preset_remesh_settings(s, iterations);
  r.sizes = sizes;
  return r;
}

}  // namespace

void check_composite(const Composite& c) {
  std::vector<int> uses(c.curves.size(), 0);
  std::vector<int> forward(c.curves.size(), 0);
  for (const CompositePatch& p : c.patches) {
    const std::size_t n = p.sides.size();
    if (n < 3 || n > 12)
      throw InputError("patch '" + p.name + "' has " + std::to_string(n) + " sides (want 3 to 12)");
    if (p.corner_directions.size() != n)
      throw InputError("patch '" + p.name + "' has " + std::to_string(p.corner_directions.size()) +
                       " corner directions for " + std::to_string(n) + " sides");
    for (const Vec3& d : p.corner_directions)
      if (!d.allFinite() || !(d.norm() > 0.0))
        throw InputError("patch '" + p.name +
                         "' has a corner direction that is not a finite non-zero vector");
    for (const PatchSide& s : p.sides)
      if (s.curve >= c.curves.size())
        throw InputError("patch '" + p.name + "' names curve " + std::to_string(s.curve) + " of " +
                         std::to_string(c.curves.size()));
    for (std::size_t k = 0; k < n; ++k)
      if (side_end(c, p.sides[k]) != side_start(c, p.sides[(k + 1) % n]))
        throw InputError("patch '" + p.name + "': side " + std::to_string(k) + " does not end where side " +
                         std::to_string((k + 1) % n) + " starts");
    for (const PatchSide& s : p.sides) {
      ++uses[s.curve];
      if (!s.reversed) ++forward[s.curve];
    }
  }
  for (std::size_t i = 0; i < c.curves.size(); ++i) {
    if (uses[i] > 2)
      throw InputError("curve " + std::to_string(i) + " bounds " + std::to_string(uses[i]) +
                       " patch sides (at most 2)");
    if (uses[i] == 2 && forward[i] != 1)
      throw InputError("curve " + std::to_string(i) +
                       " is used twice in the same direction (the patches are not oriented consistently)");
  }
}

CompositeMesh mesh_composite_projection(const Composite& c, const Settings& settings, MeshStats* stats) {
  settings.validate();
  check_composite(c);
  const auto start = std::chrono::steady_clock::now();
  const Box box = settings.box.value_or(c.box);
  const TargetSizes sizes = target_sizes(settings, valid_box(box));
  std::vector<std::unique_ptr<Sampler>> samplers;
  for (const CompositePatch& p : c.patches) samplers.push_back(std::make_unique<Sampler>(*p.surface));

  // Curve segments: the most that either patch using the curve asks for (with varying sizes each
  // reads its own function's curvature); a curve no patch uses gets no vertices.
  std::vector<int> segments(c.curves.size(), 1);
  std::vector<bool> used(c.curves.size(), false);
  for (const CompositePatch& p : c.patches)
    for (const PatchSide& s : p.sides) used[s.curve] = true;
  for (const CompositePatch& p : c.patches)
    for (const PatchSide& s : p.sides)
      segments[s.curve] = std::max(
          segments[s.curve], curve_segment_count(c.curves[s.curve], *p.surface, sizes, settings.resolution));
  std::vector<std::vector<Vec3>> dense;
  for (std::size_t i = 0; i < c.curves.size(); ++i)
    dense.push_back(used[i] ? sample_arc(c.curves[i], kCoonsSegments) : std::vector<Vec3>{});

  PatchProjectionParams params;
  params.coordinates = settings.coordinates == Settings::Coordinates::MeanValue ? CoordinateKind::MeanValue
                                                                                : CoordinateKind::Wachspress;
  params.march_steps = settings.march_steps;
  params.cos_max_ray_angle = std::cos(settings.max_ray_angle * M_PI / 180.0);
  params.region_tolerance = 0.05 * sizes.largest;

  ProjectionStats ps;
  ps.resolution = settings.resolution;
  ps.coons_base = true;
  const std::size_t patches = c.patches.size();
  std::vector<PatchPiece> pieces(patches);
  CurveSampling sampling;
  std::vector<bool> fan(patches, false);
  for (int round = 0;; ++round) {
    settings.check_cancel();
    sampling = sample_curves(c, segments, used);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, patches),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t p = r.begin(); p != r.end(); ++p)
                          pieces[p] = project_patch_on_region(
                              *samplers[p], c.patches[p], boundary_of(c.patches[p], sampling, dense), params);
                      });
    std::vector<std::size_t> rejected;
    for (std::size_t p = 0; p < patches; ++p)
      if (pieces[p].outcome != PatchOutcome::Accepted) rejected.push_back(p);
    ps.rejected_patches += rejected.size();
    if (settings.progress)
      settings.progress(
          {static_cast<std::size_t>(round + 1), static_cast<std::size_t>(settings.refinement_levels + 1)});
    if (rejected.empty()) break;
    bool refined = false;
    if (round < settings.refinement_levels)
      for (const std::size_t p : rejected)
        for (const PatchSide& s : c.patches[p].sides)
          if (segments[s.curve] < kMaxPatchResolution) {
            segments[s.curve] = std::min(kMaxPatchResolution, 2 * segments[s.curve]);
            refined = true;
          }
    if (!refined) {
      for (const std::size_t p : rejected) {
        fan[p] = true;
        pieces[p] = fan_patch(*samplers[p], c.patches[p], boundary_of(c.patches[p], sampling, dense), params);
      }
      break;
    }
    ++ps.refinements;
  }

  const auto projected = std::chrono::steady_clock::now();
  // The clean-up of each accepted patch on its own function, its boundary held.
  const int iterations = settings.remesh_iterations.value_or(kDefaultRemeshIterations);
  if (iterations > 0 && settings.max_vertices > 0 && !sizes.varies()) {
    // The clean-up splits towards the target size: refuse before it would exceed the vertex budget
    // (a mesh of equilateral triangles of side h has about area / (sqrt(3)/2 h^2) vertices).
    double area = 0.0;
    for (const PatchPiece& piece : pieces)
      for (const Triangle& t : piece.triangles) {
        const auto at = [&](std::uint32_t id) {
          return id < PatchPiece::kLocalVertex ? sampling.positions[id]
                                               : piece.points[id - PatchPiece::kLocalVertex];
        };
        area += 0.5 * (at(t[1]) - at(t[0])).cross(at(t[2]) - at(t[0])).norm();
      }
    settings.check_vertices(
        static_cast<std::size_t>(area / (0.5 * std::sqrt(3.0) * sizes.largest * sizes.largest)));
  }
  std::vector<RemeshStats> cleanup(patches);
  if (iterations > 0) {
    const RemeshSettings rs = cleanup_settings(settings, sizes, iterations);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, patches), [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t p = r.begin(); p != r.end(); ++p)
            if (!fan[p])
              pieces[p] = relax_patch(pieces[p], sampling.positions, *c.patches[p].surface, rs, cleanup[p]);
        });
  }

  CompositeMesh out;
  out.curve_segments = segments;
  out.curve_vertices = sampling.ids;
  out.mesh.positions = sampling.positions;
  out.vertex_patch.assign(sampling.positions.size(), -1);
  for (std::size_t p = 0; p < patches; ++p) {
    const auto base = static_cast<std::uint32_t>(out.mesh.positions.size());
    settings.check_vertices(base + pieces[p].points.size());
    for (const Vec3& q : pieces[p].points) {
      out.mesh.positions.push_back(q);
      out.vertex_patch.push_back(static_cast<std::int32_t>(p));
    }
    for (const Triangle& t : pieces[p].triangles) {
      Triangle g{};
      for (std::size_t i = 0; i < 3; ++i)
        g[i] = t[i] < PatchPiece::kLocalVertex ? t[i] : base + (t[i] - PatchPiece::kLocalVertex);
      out.mesh.triangles.push_back(g);
      out.triangle_patch.push_back(static_cast<std::uint32_t>(p));
    }
    ps.gradient_rays += pieces[p].gradient_rays;
    ps.unprojected_vertices += pieces[p].unprojected;
    if (fan[p])
      ++ps.fallback_cells;
    else
      ++ps.patches_by_sides[static_cast<int>(c.patches[p].sides.size())];
  }
  if (settings.vertex_roles) {
    // What made each vertex (the values of project/vertex_role.hpp): corners, curve samples, patch
    // interiors (5 where the clean-up has remeshed the patch), fan centres.
    std::vector<float> roles(out.mesh.vertex_count(), role_value(VertexRole::Interior));
    std::fill(roles.begin(), roles.begin() + static_cast<std::ptrdiff_t>(sampling.corners),
              role_value(VertexRole::Corner));
    std::fill(roles.begin() + static_cast<std::ptrdiff_t>(sampling.corners),
              roles.begin() + static_cast<std::ptrdiff_t>(sampling.positions.size()),
              role_value(VertexRole::Side));
    for (std::size_t v = sampling.positions.size(); v < roles.size(); ++v) {
      const auto p = static_cast<std::size_t>(out.vertex_patch[v]);
      if (fan[p])
        roles[v] = role_value(VertexRole::FanCentre);
      else if (iterations > 0)
        roles[v] = 5.0f;
    }
    out.mesh.set_attribute("role", std::move(roles));
  }
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
