#pragma once
// A surface seen in a rotated frame: g(y) = f(R y), so the octree of g over a box in frame coordinates
// is the octree of f in a frame rotated by R. Gradient R^T grad f, Hessian R^T H R; interval bounds
// over the user's box that holds the frame box (sound, looser than the unrotated ones).

#include <isopatch/surface.hpp>

namespace isopatch {

class RotatedSurface final : public Surface {
 public:
  /// \param rotation  a rotation matrix (its columns are the frame's axes in the user's coordinates)
  /// \param box       the default box, in frame coordinates
  RotatedSurface(const Surface& surface, const Mat3& rotation, const Box& box);

  double value(const Vec3& p) const override;
  void values(std::span<const Vec3> points, std::span<double> out) const override;
  ValueGradient value_gradient(const Vec3& p) const override;
  SecondOrder second_order(const Vec3& p) const override;
  std::optional<Interval> bound(const Box& box) const override;
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override;

 private:
  Box user_box(const Box& frame_box) const;

  const Surface& surface_;
  Mat3 r_;
};

/// The frame box holding `box` (user coordinates) for the rotation r: the bounds of its rotated corners.
Box frame_bounds(const Box& box, const Mat3& r);

}  // namespace isopatch
