// Wachspress and mean value coordinates in the division-free product form.
//
// Floater-Hormann-Kos write the weights of the three-point family as
//   w_k = (r_{k+1}^p A_{k-1} - r_k^p B_k + r_{k-1}^p A_k) / (A_{k-1} A_k),
// with A_k = area(x, V_k, V_{k+1}), B_k = area(x, V_{k-1}, V_{k+1}) and r_k = |x - V_k|. The quotient
// blows up on the sides (A_k = 0). Multiplying every weight by prod_j A_j removes the division:
//   w^_k = (r_{k+1}^p A_{k-1} - r_k^p B_k + r_{k-1}^p A_k) * prod_{j != k-1, k} A_j.
// For p = 0 the bracket equals C_k = area(V_{k-1}, V_k, V_{k+1}) identically; we use C_k directly, so
// Wachspress has no cancellation at all. For p = 1 the three terms of the bracket share one sign near
// the boundary (where accuracy matters), so the bracket is accurate there as well; it can cancel only
// in the middle of the domain, where it stays bounded away from 0.
//
// On side k every product containing A_k vanishes, leaving only w^_k and w^_{k+1}: the coordinates are
// linear on the side. At a vertex both adjacent areas vanish and the mean value weights become 0/0,
// so vertices are special-cased. For n <= 12 the products of areas (each of order 1) neither overflow nor
// underflow in the closed domain away from the vertex tolerance.
#include "ngon/barycentric.hpp"

#include <array>
#include <cassert>

namespace isopatch {
void barycentric_coordinates(const Domain& domain, const Vec2& x, CoordinateKind kind,
                             std::span<double> lambda) {
  const int n = domain.sides();
  assert(lambda.size() == static_cast<std::size_t>(n));
  const auto at = [n](int k) { return static_cast<std::size_t>(((k % n) + n) % n); };

  std::array<Vec2, Domain::kMaxSides> d;  // V_k - x
  std::array<double, Domain::kMaxSides> r{};
  for (int k = 0; k < n; ++k) {
    d[at(k)] = domain.vertex(k) - x;
    r[at(k)] = d[at(k)].norm();
  }
  for (int k = 0; k < n; ++k) {
    if (r[at(k)] <= kBarycentricVertexTolerance) {
      for (int j = 0; j < n; ++j) lambda[at(j)] = j == k ? 1.0 : 0.0;
      return;
    }
  }

  std::array<double, Domain::kMaxSides> area{};  // A_k (twice the signed area; factors of 2 cancel)
  for (int k = 0; k < n; ++k) area[at(k)] = cross(d[at(k)], d[at(k + 1)]);

  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    double bracket = 0.0;
    if (kind == CoordinateKind::Wachspress) {
      bracket = cross(domain.vertex(k) - domain.vertex(k - 1), domain.vertex(k + 1) - domain.vertex(k - 1));
    } else {
      const double b = cross(d[at(k - 1)], d[at(k + 1)]);  // B_k
      bracket = r[at(k + 1)] * area[at(k - 1)] - r[at(k)] * b + r[at(k - 1)] * area[at(k)];
    }
    double w = bracket;
    for (int j = k + 1; j < k + n - 1; ++j) w *= area[at(j)];  // every j except k - 1 and k
    lambda[at(k)] = w;
    sum += w;
  }
  assert(sum != 0.0);
  for (int k = 0; k < n; ++k) lambda[at(k)] /= sum;
}

}  // namespace isopatch
