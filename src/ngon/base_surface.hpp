#pragma once
/// \file base_surface.hpp
/// Base surfaces of an n-sided patch: the map from generalized barycentric coordinates lambda_0 ..
/// lambda_{n-1} of a domain point (barycentric.hpp) to a point in space, from which the projection
/// mesher marches onto f = 0 (Sipos & Salvi 2021, sec. 2.2; docs/algorithms.md 3.5). An open set
/// (barycentric, multi-sided C0 Coons, later others), hence the one level of virtual dispatch.
/// Indexing follows domain.hpp: corner k sits at V_k, side k runs from V_k to V_{k+1}.

#include <isopatch/geometry.hpp>
#include <isopatch/stage_settings.hpp>

#include <memory>
#include <span>
#include <vector>

namespace isopatch {

class BaseSurface {
 public:
  virtual ~BaseSurface() = default;
  /// Number of sides n.
  virtual int sides() const = 0;
  /// The base point at coordinates lambda. \pre lambda.size() == sides(), sum lambda_k = 1.
  virtual Vec3 evaluate(std::span<const double> lambda) const = 0;
};

/// The paper's eq. (1): p(x) = sum_k lambda_k(x) Q_k. On side k it is the chord from Q_k to Q_{k+1}.
class BarycentricBase final : public BaseSurface {
 public:
  /// \param corners  Q_0 .. Q_{n-1}. \throw InputError unless 3 <= n <= 12.
  explicit BarycentricBase(std::vector<Vec3> corners);
  int sides() const override { return static_cast<int>(corners_.size()); }
  Vec3 evaluate(std::span<const double> lambda) const override;

 private:
  std::vector<Vec3> corners_;
};

/// What a base surface is built from: the patch's corners Q_0 .. Q_{n-1} and, for kinds that need
/// them (needs_side_curves()), per side k a dense polyline from corner k to corner k + 1.
struct BaseInputs {
  std::vector<Vec3> corners;
  std::vector<std::vector<Vec3>> side_curves;
};

/// Whether the base of `kind` is built over dense side curves, which the producer must trace (a cell's
/// face curves) or sample (a composite's curves). \pre kind is not Automatic (the producer resolves it).
bool needs_side_curves(PatchSettings::Base kind);

/// The one place a base kind becomes a base surface: Barycentric over the corners, Coons over the side
/// curves (coons_patch.hpp). A new kind of base is added here and in PatchSettings::Base.
/// \pre kind is not Automatic. \throw InputError as the kind's constructor (sides out of 3..12,
///      curves that do not close); Error(Internal) for Automatic.
std::unique_ptr<BaseSurface> make_base_surface(PatchSettings::Base kind, BaseInputs inputs);

}  // namespace isopatch
