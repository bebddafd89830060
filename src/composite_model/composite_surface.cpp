/// \file composite_surface.cpp
/// The composite as one piecewise Surface (composite_surface.hpp).
#include "composite_model/composite_surface.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace isopatch {

namespace {

const Composite& checked(const std::shared_ptr<const Composite>& c) {
  if (!c) throw InputError("a composite surface needs a composite");
  if (c->patches.empty()) throw InputError("composite '" + c->name + "' has no patch");
  for (const CompositePatch& p : c->patches) {
    if (!p.surface) throw InputError("patch '" + p.name + "' of composite '" + c->name + "' has no function");
    for (const SurfacePtr& b : p.bounds)
      if (!b) throw InputError("patch '" + p.name + "' of composite '" + c->name + "' has an empty bound");
  }
  if (!c->box.valid()) throw InputError("composite '" + c->name + "' has no valid box");
  return *c;
}

}  // namespace

CompositeSurface::CompositeSurface(std::shared_ptr<const Composite> composite)
    : Surface(checked(composite).name, checked(composite).box), composite_(std::move(composite)) {}

double CompositeSurface::region_depth(std::size_t k, const Vec3& p) const {
  double depth = std::numeric_limits<double>::infinity();
  for (const SurfacePtr& b : composite_->patches[k].bounds) {
    const double v = b->value(p);
    if (std::isnan(v)) return -std::numeric_limits<double>::infinity();
    depth = std::min(depth, v);
  }
  return depth;
}

std::size_t CompositeSurface::patch_at(const Vec3& p) const {
  // Regions may overlap far from the surface (prisms perpendicular to a face hold the opposite face
  // too), so among the regions that hold p the patch whose zero set is nearest wins; the deepest
  // region only where none holds p.
  std::size_t deepest = 0;
  double deepest_depth = -std::numeric_limits<double>::infinity();
  std::size_t nearest = composite_->patches.size();
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < composite_->patches.size(); ++k) {
    const double d = region_depth(k, p);
    if (d > deepest_depth) {
      deepest = k;
      deepest_depth = d;
    }
    if (!(d >= 0.0)) continue;
    const ValueGradient vg = composite_->patches[k].surface->value_gradient(p);
    const double g = vg.gradient.norm();
    double distance = std::abs(vg.value) / g;
    if (!std::isfinite(distance)) distance = std::numeric_limits<double>::infinity();
    if (distance < nearest_distance || nearest == composite_->patches.size()) {
      nearest = k;
      nearest_distance = distance;
    }
  }
  return nearest < composite_->patches.size() ? nearest : deepest;
}

double CompositeSurface::value(const Vec3& p) const {
  return composite_->patches[patch_at(p)].surface->value(p);
}

ValueGradient CompositeSurface::value_gradient(const Vec3& p) const {
  return composite_->patches[patch_at(p)].surface->value_gradient(p);
}

SecondOrder CompositeSurface::second_order(const Vec3& p) const {
  return composite_->patches[patch_at(p)].surface->second_order(p);
}

}  // namespace isopatch
