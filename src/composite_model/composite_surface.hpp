#pragma once
/// \file composite_surface.hpp
/// A composite (composite.hpp) seen as one Surface: at a point x it is the function of the patch that
/// owns x. A patch owns x when its region holds x (min_j b_kj(x) >= 0) and, of the patches whose regions
/// do, its zero set is nearest (|f| / |grad f| smallest); where no region holds x, the patch whose
/// region holds it most deeply (k = argmax_k min_j b_kj(x)). Regions that tile space near the surface
/// make this the plain piecewise function there; the nearest-zero-set rule decides where regions overlap
/// far from the surface (the prism over a face of a box also holds the opposite face). Where neighbouring
/// patches share their bounding surface and ribbon, the piecewise function is C1 across the shared bound
/// (Varady, Benko, Kos & Rockwood 2001: an I-patch agrees with its ribbon in value and gradient on the
/// whole bounding surface). Marching Cubes, the analysis and the renderer use it as any other surface
/// (Sipos & Salvi 2021, sec. 4, compare Marching Cubes on such a composite with projection).

#include <isopatch/surface.hpp>

#include <cstddef>
#include <memory>

#include "composite_model/composite.hpp"

namespace isopatch {

class CompositeSurface final : public Surface {
 public:
  /// \throw InputError when the composite has no patch, a patch has no surface or a null bound, or
  ///        the composite's box is not valid (finite, lo < hi).
  explicit CompositeSurface(std::shared_ptr<const Composite> composite);

  /// The value, gradient and Hessian of patch_at(p)'s function at p.
  double value(const Vec3& p) const override;
  ValueGradient value_gradient(const Vec3& p) const override;
  SecondOrder second_order(const Vec3& p) const override;

  /// The patch that owns p (see above); the lowest k on ties. A bound that is NaN at p counts as
  /// -infinity (p is not inside that region); a patch function or gradient that is not finite (or a
  /// zero gradient) at p counts as infinitely far.
  std::size_t patch_at(const Vec3& p) const;
  /// min_j b_kj(p) over the bounds of patch k (+infinity for a patch without bounds; -infinity when a
  /// bound is NaN there). \pre k < composite().patches.size().
  double region_depth(std::size_t k, const Vec3& p) const;

  const Composite& composite() const { return *composite_; }
  const std::shared_ptr<const Composite>& shared() const { return composite_; }

 private:
  std::shared_ptr<const Composite> composite_;
};

}  // namespace isopatch
