/// \file curve_edge_points.cpp
/// The refined points of a composite's curve edges (curve_edge_points.hpp).
#include "composite_mesher/curve_edge_points.hpp"

#include <algorithm>

#include "composite_mesher/curve_samples.hpp"

namespace isopatch {

CurveEdgePoints::CurveEdgePoints(const Composite& composite, const std::vector<int>& curve_segments,
                                 const std::vector<std::vector<std::uint32_t>>& curve_vertices)
    : composite_(composite), curve_segments_(curve_segments) {
  for (std::size_t c = 0; c < curve_vertices.size(); ++c) {
    const std::vector<std::uint32_t>& ids = curve_vertices[c];
    for (std::size_t i = 0; i + 1 < ids.size(); ++i) {
      const std::uint32_t a = ids[i], b = ids[i + 1];
      by_edge_[{std::min(a, b), std::max(a, b)}] =
          Segment{static_cast<std::uint32_t>(c), static_cast<int>(i), a < b};
    }
  }
}

bool CurveEdgePoints::points(std::uint32_t a, std::uint32_t b, int level, std::span<Vec3> out) {
  const auto it = by_edge_.find({a, b});
  if (it == by_edge_.end()) return false;
  if (level != fine_level_) {  // one level per refinement; another level samples again
    fine_.clear();
    fine_level_ = level;
  }
  const Segment& s = it->second;
  auto [at, fresh] = fine_.try_emplace(s.curve);
  if (fresh) at->second = sample_curve(composite_, s.curve, curve_segments_[s.curve] * level);
  const std::vector<Vec3>& samples = at->second;
  // Sample i * level + j lies j / level of the way along segment i, from sample i.
  for (int j = 1; j < level; ++j) {
    const int along = s.lower_first ? j : level - j;
    out[static_cast<std::size_t>(j - 1)] = samples[static_cast<std::size_t>(s.segment * level + along)];
  }
  return true;
}

}  // namespace isopatch
