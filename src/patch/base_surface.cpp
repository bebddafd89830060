// The barycentric base surface; see base_surface.hpp.
#include "patch/base_surface.hpp"

#include <isopatch/error.hpp>

#include <string>
#include <utility>

#include "patch/domain.hpp"

namespace isopatch {

BarycentricBase::BarycentricBase(std::vector<Vec3> corners) : corners_(std::move(corners)) {
  const auto n = static_cast<int>(corners_.size());
  if (n < Domain::kMinSides || n > Domain::kMaxSides)
    throw InputError("barycentric base: number of corners " + std::to_string(n) + " is outside 3..16");
}

Vec3 BarycentricBase::evaluate(std::span<const double> lambda) const {
  Vec3 p = Vec3::Zero();
  for (std::size_t k = 0; k < corners_.size(); ++k) p += lambda[k] * corners_[k];
  return p;
}

}  // namespace isopatch
