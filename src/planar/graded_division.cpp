// Graded division of a segment (graded_division.hpp).
#include "planar/graded_division.hpp"

#include <algorithm>
#include <cmath>

namespace isopatch::planar {

std::vector<double> graded_division(double length, double size_a, double size_b) {
  const double change = size_b - size_a;
  const bool even = std::abs(change) <= 1e-6 * std::max(size_a, size_b);
  // The integral of 1 / s(x) dx over the segment, s(x) = size_a + change * x / length.
  const double count = even ? length / size_a : length * std::log(size_b / size_a) / change;
  const long n = std::max(1L, std::lround(count));
  std::vector<double> t;
  t.reserve(static_cast<std::size_t>(n - 1));
  for (long k = 1; k < n; ++k) {
    const double share = static_cast<double>(k) / static_cast<double>(n);
    // s(X) = size_a (size_b / size_a)^share where the integral reaches share of the whole.
    t.push_back(even ? share : (size_a * std::pow(size_b / size_a, share) - size_a) / change);
  }
  return t;
}

}  // namespace isopatch::planar
