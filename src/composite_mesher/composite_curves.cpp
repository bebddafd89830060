/// \file composite_curves.cpp
/// The curves of a composite as the mesher shares them (composite_curves.hpp).
#include "composite_mesher/composite_curves.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "composite_mesher/curve_samples.hpp"
#include "surface/target_size.hpp"

namespace isopatch {

namespace {

/// Segments of the dense polyline of a curve for the Coons base: enough that the polyline's chord error
/// is far below an edge's for curves of up to a quarter turn per patch.
constexpr int kCoonsSegments = 128;
/// Points of a curve where a varying target size is read: the curve gets the smallest size among them.
constexpr int kSizeSamples = 9;

using CornerKey = std::array<double, 3>;
CornerKey corner_key(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

/// The segments a patch asks of one of its curves: the curve's length over the target size there on the
/// patch's function (rounded, 1..kMaxPatchResolution), or the fixed resolution.
int curve_segment_count(const Composite& c, std::size_t curve, const Surface& surface,
                        const TargetSizes& sizes, int resolution) {
  const double length = curve_length(c, curve);
  if (resolution > 0) return resolution;
  double h = sizes.largest;
  if (sizes.varies()) {
    if (is_traced(c, curve)) {
      for (const Vec3& p : sample_curve(c, curve, kSizeSamples - 1))
        h = std::min(h, target_size(surface, sizes, p));
    } else {
      const ConicArc& arc = c.curves[curve];
      for (int i = 0; i < kSizeSamples; ++i)
        h = std::min(h, target_size(surface, sizes, arc.point(static_cast<double>(i) / (kSizeSamples - 1))));
    }
  }
  const double count = std::round(length / h);
  return static_cast<int>(std::clamp(count, 1.0, static_cast<double>(kMaxPatchResolution)));
}

}  // namespace

CurvePlan plan_curves(const Composite& c, const TargetSizes& sizes, int resolution) {
  CurvePlan plan;
  plan.segments.assign(c.curves.size(), 1);
  plan.used.assign(c.curves.size(), false);
  for (const CompositePatch& p : c.patches)
    for (const PatchSide& s : p.sides) plan.used[s.curve] = true;
  // With varying sizes each patch reads its own function's curvature.
  for (const CompositePatch& p : c.patches)
    for (const PatchSide& s : p.sides)
      plan.segments[s.curve] =
          std::max(plan.segments[s.curve], curve_segment_count(c, s.curve, *p.surface, sizes, resolution));
  for (std::size_t i = 0; i < c.curves.size(); ++i)
    plan.dense.push_back(plan.used[i] ? sample_curve(c, i, kCoonsSegments) : std::vector<Vec3>{});
  return plan;
}

CurveSampling sample_curves(const Composite& c, const CurvePlan& plan) {
  const std::vector<int>& segments = plan.segments;
  const std::vector<bool>& used = plan.used;
  CurveSampling s;
  std::map<CornerKey, std::uint32_t> corner_of;
  const auto corner = [&](const Vec3& p) {
    const auto [it, fresh] = corner_of.emplace(corner_key(p), static_cast<std::uint32_t>(s.positions.size()));
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
    s.points[i] = sample_curve(c, i, segments[i]);
    s.ids[i].push_back(ends[i].first);
    for (std::size_t j = 1; j + 1 < s.points[i].size(); ++j) {
      s.ids[i].push_back(static_cast<std::uint32_t>(s.positions.size()));
      s.positions.push_back(s.points[i][j]);
    }
    s.ids[i].push_back(ends[i].second);
  }
  return s;
}

PatchBoundary boundary_of(const CompositePatch& patch, const CurveSampling& s, const CurvePlan& plan) {
  const std::vector<std::vector<Vec3>>& dense = plan.dense;
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

}  // namespace isopatch
