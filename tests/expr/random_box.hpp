#pragma once
// Random boxes for the tests of interval enclosures.

#include <isopatch/geometry.hpp>

#include <cmath>
#include <random>

namespace isopatch::test {

/// A random box around a random centre in `region`, sizes from 1e-4 to 4; every third one (by `index`)
/// straddles 0 on each axis.
inline Box random_box(const Box& region, std::mt19937_64& rng, int index) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Box b;
  for (int k = 0; k < 3; ++k) {
    const double half = std::pow(10.0, -4.0 + 4.6 * u(rng)) / 2.0;
    double c = region.lo[k] + u(rng) * (region.hi[k] - region.lo[k]);
    if (index % 3 == 0) c = (u(rng) - 0.5) * half;  // straddles zero
    b.lo[k] = c - half;
    b.hi[k] = c + half;
  }
  return b;
}

}  // namespace isopatch::test
