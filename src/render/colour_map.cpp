#include "render/colour_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace isopatch::render {
namespace {

struct Stop {
  double t;
  Colour colour;
};

// Linear interpolation between stops sorted by t; saturates at both ends.
template <std::size_t N>
Colour interpolate(const std::array<Stop, N>& stops, double t) {
  if (t <= stops.front().t) return stops.front().colour;
  for (std::size_t i = 1; i < N; ++i) {
    if (t <= stops[i].t) {
      const double s = (t - stops[i - 1].t) / (stops[i].t - stops[i - 1].t);
      return (1.0 - s) * stops[i - 1].colour + s * stops[i].colour;
    }
  }
  return stops.back().colour;
}

}  // namespace

Colour diverging_colour(double t) {
  static const std::array<Stop, 5> stops = {{{-1.0, Colour(0.13, 0.27, 0.68)},
                                             {-0.5, Colour(0.52, 0.68, 0.90)},
                                             {0.0, Colour(1.0, 1.0, 1.0)},
                                             {0.5, Colour(0.93, 0.58, 0.48)},
                                             {1.0, Colour(0.70, 0.09, 0.15)}}};
  return interpolate(stops, t);
}

Colour sequential_colour(double t) {
  static const std::array<Stop, 4> stops = {{{0.0, Colour(1.0, 1.0, 0.80)},
                                             {1.0 / 3.0, Colour(0.99, 0.80, 0.38)},
                                             {2.0 / 3.0, Colour(0.92, 0.36, 0.14)},
                                             {1.0, Colour(0.50, 0.0, 0.10)}}};
  return interpolate(stops, t);
}

double robust_magnitude(const std::vector<double>& values, double percentile) {
  std::vector<double> magnitudes;
  magnitudes.reserve(values.size());
  for (const double v : values)
    if (std::isfinite(v)) magnitudes.push_back(std::abs(v));
  if (magnitudes.empty()) return 0.0;
  const double n = static_cast<double>(magnitudes.size());
  const auto rank = static_cast<std::size_t>(std::clamp(std::ceil(percentile / 100.0 * n), 1.0, n)) - 1;
  std::nth_element(magnitudes.begin(), magnitudes.begin() + static_cast<std::ptrdiff_t>(rank),
                   magnitudes.end());
  return magnitudes[rank];
}

}  // namespace isopatch::render
