/// \file curve_samples.cpp
/// Equal arc-length samples of the composite's arcs (curve_samples.hpp).
#include "composite_mesher/curve_samples.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace isopatch {

namespace {

constexpr int kTable = 512;

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

}  // namespace isopatch
