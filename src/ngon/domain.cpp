// The regular n-gon domain; see domain.hpp for the indexing convention.
#include "ngon/domain.hpp"

#include <isopatch/error.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace isopatch {

Domain::Domain(int n) : n_(n) {
  if (n < kMinSides || n > kMaxSides) {
    throw InputError("patch domain: number of sides " + std::to_string(n) + " is outside 3..16");
  }
  vertices_.fill(Vec2::Zero());
  if (n == 4) {
    // The square keeps exact coordinates (cos(pi/2) is not exactly 0) and makes Wachspress bilinear.
    vertices_[0] = Vec2(1.0, 1.0);
    vertices_[1] = Vec2(-1.0, 1.0);
    vertices_[2] = Vec2(-1.0, -1.0);
    vertices_[3] = Vec2(1.0, -1.0);
    return;
  }
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / n;
    vertices_[static_cast<std::size_t>(k)] = Vec2(std::cos(angle), std::sin(angle));
  }
}

Vec2 Domain::side_point(int k, double t) const {
  // Written as a two-term blend (not V_k + t (V_{k+1} - V_k)) so that both ends are reproduced exactly.
  return (1.0 - t) * vertex(k) + t * vertex(k + 1);
}

}  // namespace isopatch
