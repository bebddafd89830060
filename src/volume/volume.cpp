// The sampled volume's checks (volume.hpp).
#include <isopatch/error.hpp>
#include <isopatch/volume.hpp>

#include <cmath>
#include <string>

namespace isopatch {

std::size_t checked_sample_count(const std::array<std::size_t, 3>& shape) {
  std::size_t count = 1;
  for (const std::size_t n : shape) {
    if (n == 0 || n > kMaxVolumeSamples || count > kMaxVolumeSamples / n) return 0;
    count *= n;
  }
  return count;
}

Box Volume::extent() const {
  Box box;
  box.lo = origin;
  for (int a = 0; a < 3; ++a)
    box.hi[a] = origin[a] + static_cast<double>(shape[static_cast<std::size_t>(a)] - 1) * spacing[a];
  return box;
}

void Volume::validate() const {
  const auto shape_text = [this] {
    return std::to_string(shape[0]) + " x " + std::to_string(shape[1]) + " x " + std::to_string(shape[2]);
  };
  for (const std::size_t n : shape)
    if (n < 2)
      throw InputError("the volume is " + shape_text() + ": every side needs at least 2 samples", "volume");
  const std::size_t count = checked_sample_count(shape);
  if (count == 0)
    throw InputError(
        "the volume is " + shape_text() + ": more than " + std::to_string(kMaxVolumeSamples) + " samples",
        "volume");
  if (samples.size() != count)
    throw InputError(
        "the volume is " + shape_text() + " but holds " + std::to_string(samples.size()) + " samples",
        "volume");
  validate_geometry();
  for (std::size_t n = 0; n < count; ++n)
    if (!std::isfinite(samples[n])) {
      const std::size_t k = n % shape[2], j = (n / shape[2]) % shape[1], i = n / (shape[2] * shape[1]);
      throw InputError("the volume has " + std::string(std::isnan(samples[n]) ? "NaN" : "an infinity") +
                           " at index (" + std::to_string(i) + ", " + std::to_string(j) + ", " +
                           std::to_string(k) + ")",
                       "volume");
    }
}

void Volume::validate_geometry() const {
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(spacing[a]) || spacing[a] <= 0.0)
      throw InputError("the spacing must be finite and > 0 on every axis", "spacing");
    if (!std::isfinite(origin[a])) throw InputError("the origin must be finite", "origin");
  }
  if (!extent().valid()) throw InputError("the volume's extent is not a finite box", "spacing");
}

}  // namespace isopatch
