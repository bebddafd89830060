// Validation of RemeshSettings (remesh_checks.hpp).
#include "remesh/remesh_checks.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <string>

namespace isopatch {

void check_remesh_settings(const RemeshSettings& s) {
  validate_region(s.cut_planes, "cut_planes");
  const TargetSizes& sizes = s.sizes;
  if (!(std::isfinite(sizes.largest) && sizes.largest > 0.0))
    throw SettingError("sizes.largest", "remesh: the edge length must be a positive number");
  if (sizes.max_error && !(std::isfinite(*sizes.max_error) && *sizes.max_error > 0.0))
    throw SettingError("sizes.max_error", "remesh: the maximum error must be a positive number");
  if (sizes.varies() && !(sizes.smallest > 0.0 && sizes.smallest <= sizes.largest))
    throw SettingError("sizes.smallest",
                       "remesh: the smallest size must be positive and at most the edge length");
  if (!(s.grading > 0.0 && s.grading <= 1.0))
    throw SettingError("grading", "remesh: grading must lie in (0, 1]");
  s.cleanup.validate();
}

}  // namespace isopatch
