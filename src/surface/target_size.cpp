// Target sizes from Settings (see target_size.hpp).
#include "surface/target_size.hpp"

#include <isopatch/error.hpp>
#include <isopatch/level_set_curvature.hpp>

#include <algorithm>
#include <cmath>

namespace isopatch {

double target_size(const Surface& surface, const TargetSizes& spec, const Vec3& p) {
  double h = spec.largest;
  if (spec.max_error)
    h = std::min(h, size_for_error(max_abs_principal_curvature(surface, p), *spec.max_error));
  if (spec.user) {
    const double u = spec.user(p);
    if (!(std::isfinite(u) && u > 0.0))
      throw SettingError("size_field", "the size field must be positive and finite");
    h = std::min(h, u);
  }
  return std::clamp(h, spec.smallest, spec.largest);
}

}  // namespace isopatch
