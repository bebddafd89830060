#pragma once
/// \file volume.hpp
/// A sampled scalar volume: values on a regular axis-aligned grid, as a CT scan, a simulation or a
/// signed-distance grid gives them. Axis order follows numpy (and scikit-image): array axis 0 is x,
/// axis 1 is y, axis 2 is z, and the sample at index (i, j, k) sits at origin + (i sx, j sy, k sz).

#include <isopatch/geometry.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace isopatch {

/// The most samples a volume may hold (2^30, 8 GiB of doubles): a larger header is taken as a lie.
inline constexpr std::size_t kMaxVolumeSamples = std::size_t{1} << 30;

struct Volume {
  /// Samples along x, y, z (array axes 0, 1, 2); each at least 2.
  std::array<std::size_t, 3> shape{0, 0, 0};
  /// Distance between neighbouring samples along x, y, z; each finite and > 0.
  Vec3 spacing = Vec3::Ones();
  /// Position of sample (0, 0, 0); finite.
  Vec3 origin = Vec3::Zero();
  /// shape[0] * shape[1] * shape[2] values in C order: samples[(i * shape[1] + j) * shape[2] + k].
  std::vector<double> samples;

  double at(std::size_t i, std::size_t j, std::size_t k) const {
    return samples[(i * shape[1] + j) * shape[2] + k];
  }
  /// The box the samples span: origin to origin + (shape - 1) * spacing.
  Box extent() const;
  /// Checks the shape (each side >= 2, at most kMaxVolumeSamples in all, one value per sample), the
  /// spacing and origin (finite, spacing > 0) and the samples (finite).
  /// \throw InputError naming the first violation ("the volume has NaN at index (3, 4, 5)"); the
  ///        setting is "volume", "spacing" or "origin".
  void validate() const;
  /// The part of validate() that needs no samples: spacing and origin finite, spacing > 0, a finite
  /// extent. \throw InputError as validate() (setting "spacing" or "origin").
  void validate_geometry() const;
};

/// The product of `shape`, or 0 when it exceeds kMaxVolumeSamples (so no product can overflow).
std::size_t checked_sample_count(const std::array<std::size_t, 3>& shape);

}  // namespace isopatch
