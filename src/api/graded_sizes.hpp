#pragma once
// A graded size field made of point sources (docs/algorithms.md 4.11, 4.12): at p, the smallest over the
// sources of size_i + grading * |p - point_i|, capped at the edge length. Sources come from cut features
// (cut_feature_sizes.hpp), from rims that turn within an edge (curvature_feature_sizes.hpp) and from
// singular points; the field is what the projection mesher and the clean-up shrink their sizes to.

#include <isopatch/geometry.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace isopatch {

/// One point that asks for an edge length below the requested one.
struct SizeSource {
  Vec3 point = Vec3::Zero();
  double size = 0.0;
  double grading = 0.0;  ///< how fast the size grows away from it; 0: the field's own
};

/// The lower envelope of graded cones, one per source (each with its own grading, or the field's). Queries
/// are a branch-and-bound descent of a bounding-box tree (each node keeps its smallest size), so a field of
/// 1e5 sources costs a few dozen distance evaluations per query where the sources lie on a curve or a
/// surface.
class GradedSizes {
 public:
  GradedSizes() = default;
  /// \pre largest > 0, grading > 0, every source finite with grading 0 (then `grading`) or > 0; sources
  /// with size >= largest are dropped.
  GradedSizes(std::vector<SizeSource> sources, double largest, double grading);

  /// min(largest, min_i size_i + grading_i |p - point_i|): the exact minimum (pruning only skips nodes
  /// whose bound is not smaller), deterministic. Thread-safe (const, no caching).
  double at(const Vec3& p) const;
  bool empty() const { return sources_.empty(); }
  std::size_t source_count() const { return sources_.size(); }
  /// The smallest size asked for (largest when empty).
  double smallest() const;
  /// The bounding box of the sources (invalid when empty).
  Box extent() const;

 private:
  struct Node {
    Box bounds;
    double smallest = 0.0;               ///< the smallest size of its sources
    double gentlest = 0.0;               ///< the smallest grading of its sources
    std::uint32_t first = 0, count = 0;  ///< a leaf's sources (count > 0), in sources_ order
    std::uint32_t left = 0, right = 0;   ///< an inner node's children (count == 0)
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count);

  std::vector<SizeSource> sources_;
  std::vector<Node> nodes_;
  double largest_ = 0.0;
};

}  // namespace isopatch
