/// \file base_surface.cpp
/// The barycentric base surface and the factory of base surfaces (base_surface.hpp).
#include "ngon/base_surface.hpp"

#include <isopatch/error.hpp>

#include <string>
#include <utility>

#include "ngon/coons_patch.hpp"
#include "ngon/domain.hpp"
#include "ngon/polyline_curve.hpp"

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

bool needs_side_curves(PatchSettings::Base kind) {
  return kind == PatchSettings::Base::Coons;
}

std::unique_ptr<BaseSurface> make_base_surface(PatchSettings::Base kind, BaseInputs inputs) {
  switch (kind) {
    case PatchSettings::Base::Barycentric:
      return std::make_unique<BarycentricBase>(std::move(inputs.corners));
    case PatchSettings::Base::Coons: {
      std::vector<PolylineCurve> curves;
      for (std::vector<Vec3>& side : inputs.side_curves) curves.emplace_back(std::move(side));
      return std::make_unique<CoonsPatch>(std::move(curves));
    }
    case PatchSettings::Base::Automatic:
      break;
  }
  throw Error(ErrorKind::Internal, "make_base_surface: the producer must resolve the automatic base");
}

}  // namespace isopatch
