#pragma once
/// \file curve_edge_points.hpp
/// The points a refinement puts on a base edge that lies on one of a composite's curves: the curve
/// sampled at k times the segments the base sampled it with (curve_samples.hpp), the samples between
/// the edge's two ends. They depend on the curve and the edge alone, so the two patches beside the
/// edge, and two blocks of a base refined apart (isopatch/blocks.hpp), make them to the bit.

#include <isopatch/geometry.hpp>

#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "composite_model/composite.hpp"

namespace isopatch {

/// A base's curve edges and the refined samples of their curves (each curve sampled once, when an
/// edge of it is first asked for). Not thread-safe: refine_pieces() asks from one thread.
class CurveEdgePoints {
 public:
  /// `curve_segments` and `curve_vertices` as in CompositeMesh (per curve: its segment count and its
  /// base vertices from start to end, or none). The composite must outlive this object.
  /// \pre the curves are the composite's (refine_composite() and refine_block() check it).
  CurveEdgePoints(const Composite& composite, const std::vector<int>& curve_segments,
                  const std::vector<std::vector<std::uint32_t>>& curve_vertices);

  /// For the base edge from base vertex a to base vertex b (a < b) on a curve: writes the `level` - 1
  /// points at j / level of the way from a to b along the curve (j = 1..level-1) into `out` and returns
  /// true; returns false for an edge on no curve. \pre out.size() == level - 1.
  bool points(std::uint32_t a, std::uint32_t b, int level, std::span<Vec3> out);

 private:
  /// An edge's curve, its segment (between samples i and i + 1) and whether its lower end is sample i.
  struct Segment {
    std::uint32_t curve = 0;
    int segment = 0;
    bool lower_first = true;
  };
  const Composite& composite_;
  const std::vector<int>& curve_segments_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, Segment> by_edge_;
  std::map<std::uint32_t, std::vector<Vec3>> fine_;  ///< per curve asked for: its refined samples
  int fine_level_ = 0;
};

}  // namespace isopatch
