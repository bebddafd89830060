/// \file curve_samples.cpp
/// Equal arc-length samples of the composite's arcs (curve_samples.hpp).
#include "composite_mesher/curve_samples.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <optional>

#include "surface/curve_point.hpp"

namespace isopatch {

namespace {

constexpr int kTable = 512;
/// A traced curve's samples are put back on both functions to this share of the curve's length.
constexpr double kTracedTolerance = 1e-13;

const TracedCurve* traced_curve(const Composite& c, std::size_t i) {
  if (i >= c.traced.size() || c.traced[i].points.empty()) return nullptr;
  const TracedCurve& t = c.traced[i];
  if (t.points.size() < 2 || !t.first || !t.second)
    throw InputError("a traced boundary curve needs at least 2 points and both of its functions");
  for (const Vec3& p : t.points)
    if (!p.allFinite()) throw InputError("a traced boundary curve has a point that is not finite");
  return &t;
}

/// Cumulative lengths along a polyline.
std::vector<double> polyline_lengths(const std::vector<Vec3>& points) {
  std::vector<double> s(points.size(), 0.0);
  for (std::size_t k = 1; k < points.size(); ++k) s[k] = s[k - 1] + (points[k] - points[k - 1]).norm();
  if (!(s.back() > 0.0)) throw InputError("a traced boundary curve has length 0");
  return s;
}

/// Cumulative chord lengths at t = i / kTable.
std::array<double, kTable + 1> length_table(const ConicArc& arc) {
  if (!arc.start.allFinite() || !arc.control.allFinite() || !arc.end.allFinite() ||
      !std::isfinite(arc.weight))
    throw InputError("a boundary curve has a coordinate or weight that is not a finite number");
  if (!(arc.weight > 0.0)) throw InputError("a boundary curve has a weight that is not positive");
  std::array<double, kTable + 1> table{};
  Vec3 previous = arc.start;
  for (int i = 1; i <= kTable; ++i) {
    const Vec3 p = arc.point(static_cast<double>(i) / kTable);
    table[static_cast<std::size_t>(i)] = table[static_cast<std::size_t>(i - 1)] + (p - previous).norm();
    previous = p;
  }
  if (!(table[kTable] > 0.0) || !std::isfinite(table[kTable]))
    throw InputError("a boundary curve has length 0 (its end points coincide)");
  return table;
}

}  // namespace

double arc_length(const ConicArc& arc) {
  return length_table(arc)[kTable];
}

std::vector<Vec3> sample_arc(const ConicArc& arc, int segments) {
  const auto table = length_table(arc);
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(segments) + 1);
  points.push_back(arc.start);
  for (int i = 1; i < segments; ++i) {
    const double s = table[kTable] * i / segments;
    const auto it = std::upper_bound(table.begin(), table.end(), s);
    const auto j = static_cast<int>(std::clamp<std::ptrdiff_t>(it - table.begin(), 1, kTable));
    const double a = table[static_cast<std::size_t>(j - 1)];
    const double b = table[static_cast<std::size_t>(j)];
    const double u = b > a ? (s - a) / (b - a) : 0.0;
    points.push_back(arc.point((j - 1 + u) / kTable));
  }
  points.push_back(arc.end);
  return points;
}

std::vector<Vec3> side_samples(const ConicArc& arc, bool reversed, int segments) {
  std::vector<Vec3> points = sample_arc(arc, segments);
  if (reversed) std::reverse(points.begin(), points.end());
  return points;
}

bool is_traced(const Composite& c, std::size_t i) {
  return traced_curve(c, i) != nullptr;
}

double curve_length(const Composite& c, std::size_t i) {
  if (const TracedCurve* t = traced_curve(c, i)) return polyline_lengths(t->points).back();
  return arc_length(c.curves[i]);
}

std::vector<Vec3> sample_curve(const Composite& c, std::size_t i, int segments) {
  const TracedCurve* t = traced_curve(c, i);
  if (!t) return sample_arc(c.curves[i], segments);
  const std::vector<double> s = polyline_lengths(t->points);
  const double length = s.back();
  CurvePointParams params;
  params.tolerance = kTracedTolerance * length;
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(segments) + 1);
  points.push_back(t->points.front());
  for (int k = 1; k < segments; ++k) {
    const double at = length * k / segments;
    const auto it = std::upper_bound(s.begin(), s.end(), at);
    const auto j = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(it - s.begin(), 1, std::ssize(s) - 1));
    const double u = s[j] > s[j - 1] ? (at - s[j - 1]) / (s[j] - s[j - 1]) : 0.0;
    const Vec3 guess = (1.0 - u) * t->points[j - 1] + u * t->points[j];
    // A point of the chord lies within the chord's length of the curve (its sag is far less).
    params.max_step = std::max(length / segments, s[j] - s[j - 1]);
    params.max_travel = params.max_step;
    const std::optional<Vec3> p = settle_on_curve(*t->first, *t->second, guess, params);
    if (!p)
      throw EvaluationError("a sample of a traced curve could not be put back on both of its functions");
    points.push_back(*p);
  }
  points.push_back(t->points.back());
  return points;
}

}  // namespace isopatch
