#pragma once
/// \file geometry.hpp
/// Basic geometric value types shared by every module: 3D points and vectors, 3x3 matrices and
/// axis-aligned boxes. Points are in the user's units (whatever f is written in).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

namespace isopatch {

using Vec3 = Eigen::Vector3d;  ///< a point or a vector in R^3
using Mat3 = Eigen::Matrix3d;  ///< a 3x3 matrix (Hessians)

/// An axis-aligned box [lo, hi]. A valid box has finite coordinates and lo < hi on every axis.
struct Box {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();

  Vec3 size() const { return hi - lo; }
  Vec3 centre() const { return 0.5 * (lo + hi); }
  double diagonal() const { return size().norm(); }
  /// True when all coordinates are finite and lo < hi strictly on every axis.
  bool valid() const;
  /// True when p lies in the box grown by `margin` on every side.
  bool contains(const Vec3& p, double margin = 0.0) const;
};

/// Parses "x0,y0,z0,x1,y1,z1" into a box.
/// \throw InputError when the text is not six finite numbers or the box is empty or inverted.
Box parse_box(const std::string& text);

/// Formats a box as "x0,y0,z0,x1,y1,z1" (round-trips through parse_box).
std::string format_box(const Box& box);

}  // namespace isopatch
