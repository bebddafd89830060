// The Laplacian-exactness residual and sweeps: the residual vanishes on regular rings and affine
// lattices, predicts the error of the cotangent mean curvature of the analysis module on a lifted
// paraboloid, and the sweeps drive it down on a jittered planar lattice without folding a triangle,
// lowering an angle below the floor or changing the connectivity.
#include <isopatch/curvature.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/triangle_angle.hpp"
#include "remesh/editable_mesh.hpp"
#include "remesh/laplacian_exactness.hpp"

namespace isopatch {
namespace {

/// A fan of n triangles around vertex 0 at the origin, ring vertex k at radius r_k and angle a_k.
Mesh fan(const std::vector<double>& radii, const std::vector<double>& angles) {
  Mesh m;
  m.positions.push_back(Vec3::Zero());
  const std::size_t n = radii.size();
  for (std::size_t k = 0; k < n; ++k)
    m.positions.push_back({radii[k] * std::cos(angles[k]), radii[k] * std::sin(angles[k]), 0.0});
  for (std::size_t k = 0; k < n; ++k)
    m.triangles.push_back(
        {0, static_cast<std::uint32_t>(1 + k), static_cast<std::uint32_t>(1 + (k + 1) % n)});
  return m;
}

EditableMesh planar(const Mesh& m) {
  return EditableMesh(m, std::vector<Vec3>(m.positions.size(), Vec3(0, 0, 1)));
}

TEST(LaplacianExactness, RegularRingsOfValenceFourAndMoreHaveNoResidual) {
  for (int n = 4; n <= 9; ++n) {
    std::vector<double> radii(static_cast<std::size_t>(n), 0.7), angles;
    for (int k = 0; k < n; ++k) angles.push_back(2.0 * std::numbers::pi * k / n + 0.3);
    const EditableMesh m = planar(fan(radii, angles));
    EXPECT_LT(quadratic_exactness_residual(m, 0, 0, m.positions[0]).norm(), 1e-12) << "valence " << n;
  }
  // Uneven radii: not exact.
  const EditableMesh m = planar(fan({0.7, 1.0, 0.7, 0.9, 0.7, 1.0}, {0, 1, 2, 3, 4, 5.2}));
  EXPECT_GT(quadratic_exactness_residual(m, 0, 0, m.positions[0]).norm(), 0.05);
  // Valence 3: the corners at the centre are obtuse, the mixed area is no longer the Voronoi area.
  const double third = 2.0 * std::numbers::pi / 3.0;
  const EditableMesh three = planar(fan({0.7, 0.7, 0.7}, {0.0, third, 2.0 * third}));
  EXPECT_GT(quadratic_exactness_residual(three, 0, 0, three.positions[0]).norm(), 0.1);
}

TEST(LaplacianExactness, AffineLatticesHaveNoResidual) {
  // The valence-6 ring of a uniform lattice after a shear and an anisotropic scaling: every triangle
  // is congruent, and the cotangent Laplacian of such a lattice is exact for quadratics.
  Mesh m = fan({1, 1, 1, 1, 1, 1}, {0, std::numbers::pi / 3, 2 * std::numbers::pi / 3, std::numbers::pi,
                                    4 * std::numbers::pi / 3, 5 * std::numbers::pi / 3});
  for (Vec3& p : m.positions) p = Vec3(1.3 * p.x() + 0.4 * p.y(), 0.8 * p.y(), 0.0);
  const EditableMesh e = planar(m);
  EXPECT_LT(quadratic_exactness_residual(e, 0, 0, e.positions[0]).norm(), 1e-12);
  // The same ring with the centre moved off its lattice position is not exact; the residual is
  // evaluated with the centre at a trial position without changing the mesh.
  EXPECT_GT(quadratic_exactness_residual(e, 0, 0, Vec3(0.15, 0.05, 0.0)).norm(), 0.01);
  EXPECT_EQ(e.positions[0], Vec3::Zero());
}

TEST(LaplacianExactness, ResidualPredictsTheCotangentMeanCurvatureError) {
  // Lift an irregular planar fan onto the paraboloid z = eps q(x, y) / 2 with q(x, y) = t^T Q t; the
  // exact mean curvature at the apex is eps tr(Q) / 2 (to O(eps^3)), and the cotangent estimate of
  // the analysis module is eps tr(Q (I + R)) / 2 where R is the residual matrix.
  const Mesh flat = fan({0.8, 1.1, 0.9, 1.2, 0.7}, {0.1, 1.5, 2.6, 3.9, 5.0});
  const EditableMesh e = planar(flat);
  const Eigen::Vector3d r = quadratic_exactness_residual(e, 0, 0, e.positions[0]);
  Eigen::Matrix2d R;
  R << r[0], r[2] / std::sqrt(2.0), r[2] / std::sqrt(2.0), r[1];
  // The residual's frame: the unit vector orthogonal to the normal that Eigen picks, and normal x it.
  const Vec3 e1 = Vec3(0, 0, 1).unitOrthogonal(), e2 = Vec3(0, 0, 1).cross(e1);
  const double eps = 1e-4;
  const Eigen::Matrix2d quadratics[3] = {(Eigen::Matrix2d() << 1, 0, 0, 0).finished(),
                                         (Eigen::Matrix2d() << 0, 0, 0, 1).finished(),
                                         (Eigen::Matrix2d() << 0, 1, 1, 0).finished()};
  for (const Eigen::Matrix2d& Q : quadratics) {
    Mesh lifted = flat;
    for (Vec3& p : lifted.positions) {
      const Eigen::Vector2d t(p.dot(e1), p.dot(e2));
      p.z() = -0.5 * eps * t.dot(Q * t);  // below the tangent plane for Q > 0: H > 0 with normal +z
    }
    // Close the fan with a bottom cone so that the apex is an interior vertex of a closed mesh.
    lifted.positions.push_back(Vec3(0, 0, -5));
    const auto bottom = static_cast<std::uint32_t>(lifted.positions.size() - 1);
    for (std::uint32_t k = 1; k <= 5; ++k) lifted.triangles.push_back({bottom, k % 5 + 1, k});
    const DiscreteCurvature c = discrete_curvature(lifted);
    const double expected_error = 0.5 * eps * (Q * R).trace();
    const double exact = 0.5 * eps * Q.trace();
    EXPECT_NEAR(c.mean[0] - exact, expected_error, 1e-3 * eps) << Q;
  }
}

/// An n x n lattice of equilateral triangles in z = 0 (rows shifted by half a step).
Mesh lattice(int n) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({i + 0.5 * (j % 2), j * std::sqrt(3.0) / 2, 0.0});
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (j % 2 == 0) {
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      }
    }
  return m;
}

double smallest_angle_of(const EditableMesh& m) {
  double a = 180.0;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    const Triangle& tri = m.triangles[t];
    a = std::min(a, smallest_angle(m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]]));
  }
  return a;
}

TEST(LaplacianExactness, SweepsRestoreAJitteredLattice) {
  EditableMesh m = planar(lattice(12));
  ASSERT_LT(laplacian_exactness_energy(m), 1e-20);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.12, 0.12);
  for (std::uint32_t v = 0; v < m.vertex_slots(); ++v)
    if (!m.locked[v]) m.positions[v] += Vec3(jitter(rng), jitter(rng), 0.0);
  const std::vector<Triangle> triangles = m.triangles;
  const std::vector<Vec3> boundary_before = m.positions;
  const double angle_before = smallest_angle_of(m);
  const double floor = 25.0;
  int sweeps_started = 0;
  const ExactnessMoveRules rules{
      .project = [](Vec3& p, Vec3& n, double) { return p.z() == 0.0 && n == Vec3(0, 0, 1); },
      .triangle_valid =
          [&m](std::uint32_t t, std::uint32_t v, const Vec3& p, const Vec3&) {
            Vec3 x[3];
            for (int i = 0; i < 3; ++i) {
              const std::uint32_t w = m.triangles[t][static_cast<std::size_t>(i)];
              x[i] = w == v ? p : m.positions[w];
            }
            return (x[1] - x[0]).cross(x[2] - x[0]).z() > 0.0;
          },
      .size = [](std::uint32_t) { return 1.0; },
      .angle_floor = floor,
      .before_sweep = [&sweeps_started] { ++sweeps_started; }};
  double energy = laplacian_exactness_energy(m);
  const double start = energy;
  for (int s = 0; s < 20; ++s) {
    improve_laplacian_exactness(m, rules, 1);
    const double now = laplacian_exactness_energy(m);
    EXPECT_LE(now, energy * (1.0 + 1e-12)) << "sweep " << s;
    energy = now;
  }
  EXPECT_LT(energy, 0.05 * start);
  EXPECT_EQ(sweeps_started, 20);
  // A throwing hook stops before the sweep: nothing moves.
  const std::vector<Vec3> before_throw = m.positions;
  ExactnessMoveRules stopping = rules;
  stopping.before_sweep = [] { throw std::runtime_error("stop"); };
  EXPECT_THROW(improve_laplacian_exactness(m, stopping, 3), std::runtime_error);
  EXPECT_EQ(m.positions, before_throw);
  EXPECT_EQ(m.triangles, triangles);
  EXPECT_GE(smallest_angle_of(m), std::min(angle_before, floor) - 1e-9);
  for (std::uint32_t v = 0; v < m.vertex_slots(); ++v) {
    EXPECT_EQ(m.positions[v].z(), 0.0);
    if (m.locked[v]) {
      EXPECT_EQ(m.positions[v], boundary_before[v]);
    }
  }
}

}  // namespace
}  // namespace isopatch
