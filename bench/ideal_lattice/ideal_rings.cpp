// Ideal hexagonal rings on a surface and their cotangent curvature error, see ideal_rings.hpp.
#include "ideal_lattice/ideal_rings.hpp"

#include <isopatch/curvature.hpp>
#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

namespace isopatch::bench {
namespace {

constexpr int kRing = 6;

/// The point of f = 0 on the line p + z n nearest to z = 0, by Newton steps along n (each at most
/// `reach`); nullopt when |z| would exceed `reach` or the iteration does not settle.
std::optional<Vec3> lift(const Surface& surface, const Vec3& p, const Vec3& n, double reach) {
  double z = 0.0;
  for (int it = 0; it < 60; ++it) {
    const ValueGradient vg = surface.value_gradient(p + z * n);
    const double slope = vg.gradient.dot(n);
    if (!std::isfinite(vg.value) || !(std::abs(slope) > 0.0)) return std::nullopt;
    const double step = std::clamp(-vg.value / slope, -reach, reach);
    z += step;
    if (std::abs(z) > reach) return std::nullopt;
    if (std::abs(step) <= 1e-13 * reach) return p + z * n;
  }
  return std::nullopt;
}

/// Cotangent mean curvature at `centre` of the closed fan over `ring` (counter-clockwise about the
/// outward normal): discrete_curvature of the seven-vertex fan, whose centre is its only interior
/// vertex, so the value is the one `isopatch analyze` gives a mesh vertex with this ring. NaN for a
/// degenerate triangle.
double fan_mean_curvature(const Vec3& centre, const std::array<Vec3, kRing>& ring) {
  Mesh fan;
  fan.positions.reserve(kRing + 1);
  fan.positions.push_back(centre);
  fan.positions.insert(fan.positions.end(), ring.begin(), ring.end());
  for (std::uint32_t k = 0; k < kRing; ++k) fan.triangles.push_back({0, 1 + k, 1 + (k + 1) % kRing});
  return discrete_curvature(fan).mean[0];
}

/// Interior vertices of a mesh: those whose every edge has two triangles.
std::vector<std::size_t> interior_vertices(const Mesh& mesh) {
  const DiscreteCurvature d = discrete_curvature(mesh);
  std::vector<std::size_t> out;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    if (d.interior[v]) out.push_back(v);
  return out;
}

}  // namespace

IdealRingResult ideal_ring_error(const Mesh& mesh, const Surface& surface, const IdealRingOptions& options) {
  if (options.orientations < 1) throw InputError("orientations must be at least 1");
  if (options.max_samples < 1) throw InputError("max_samples must be at least 1");
  const std::vector<std::size_t> interior = interior_vertices(mesh);
  double area = 0.0, curvature_area = 0.0;
  // Largest principal curvature per vertex (graded sizes), floored so that flat parts get finite rings.
  const Box bounds = bounding_box(mesh);
  const double floor_kappa = bounds.valid() ? 4.0 / bounds.size().norm() : 0.0;
  const bool graded = options.sizes == RingSizes::Graded;
  std::vector<double> kappa(graded ? mesh.vertex_count() : 0, 0.0);
  if (graded) {
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      const double k = max_abs_principal_curvature(surface, mesh.positions[v]);
      kappa[v] = std::isfinite(k) ? std::max(k, floor_kappa) : std::numeric_limits<double>::quiet_NaN();
    }
  }
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.positions[t[0]];
    const double ta = 0.5 * (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a).norm();
    area += ta;
    if (graded) {
      const double k = (kappa[t[0]] + kappa[t[1]] + kappa[t[2]]) / 3.0;
      if (std::isfinite(k)) curvature_area += ta * k;
    }
  }
  if (interior.empty() || !(area > 0.0)) throw InputError("the mesh has no interior vertex or no area");
  // An equilateral mesh of V vertices on area A has edges of sqrt(2 A / (sqrt 3 V)) (two triangles of
  // area sqrt(3)/4 e^2 per vertex); graded, the count is the integral of 2 / (sqrt 3 e(x)^2) with
  // e = c / sqrt(kappa).
  const double vertices = static_cast<double>(mesh.vertex_count());
  const double weight = graded ? curvature_area : area;
  IdealRingResult r;
  r.edge = std::sqrt(2.0 * weight / (std::numbers::sqrt3 * vertices));
  const std::size_t stride =
      std::max<std::size_t>(1, (interior.size() + options.max_samples - 1) / options.max_samples);
  double err_mean = 0.0, err_best = 0.0, h_sq = 0.0;
  for (std::size_t i = 0; i < interior.size(); i += stride) {
    const std::size_t v = interior[i];
    const Vec3& p = mesh.positions[v];
    const SecondOrder s = surface.second_order(p);
    const double H = analytic_curvature(s).mean;
    const double edge = graded ? r.edge / std::sqrt(kappa[v]) : r.edge;
    const Vec3 n = s.gradient.normalized();
    if (!std::isfinite(H) || !std::isfinite(edge) || !n.allFinite()) {
      ++r.skipped;
      continue;
    }
    const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    double sum_sq = 0.0, best = std::numeric_limits<double>::infinity();
    int lifted = 0;
    for (int o = 0; o < options.orientations; ++o) {
      const double phi = std::numbers::pi / 3.0 * o / options.orientations;
      std::array<Vec3, kRing> ring;
      bool ok = true;
      for (int k = 0; k < kRing && ok; ++k) {
        const double angle = phi + std::numbers::pi / 3.0 * k;
        const std::optional<Vec3> q =
            lift(surface, p + edge * (std::cos(angle) * e1 + std::sin(angle) * e2), n, edge);
        if (q) ring[static_cast<std::size_t>(k)] = *q;
        ok = q.has_value();
      }
      const double hd = ok ? fan_mean_curvature(p, ring) : std::numeric_limits<double>::quiet_NaN();
      if (!std::isfinite(hd)) continue;
      const double e2sq = (hd - H) * (hd - H);
      sum_sq += e2sq, best = std::min(best, e2sq), ++lifted;
    }
    if (lifted == 0) {
      ++r.skipped;
      continue;
    }
    err_mean += sum_sq / lifted, err_best += best, h_sq += H * H, ++r.samples;
  }
  r.nrms_mean = h_sq > 0.0 ? std::sqrt(err_mean / h_sq) : std::numeric_limits<double>::quiet_NaN();
  r.nrms_best = h_sq > 0.0 ? std::sqrt(err_best / h_sq) : std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace isopatch::bench
