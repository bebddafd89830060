#pragma once
// Tangential vertex moves that make the cotangent Laplacian exact for quadratic functions.
//
// The cotangent mean-curvature normal of Meyer, Desbrun, Schroeder & Barr (2003) at a vertex v is
// sum_j (cot a_j + cot b_j)(x_v - x_j) / (2 A_v) with A_v the mixed Voronoi area. Write each edge in
// v's tangent plane as t_j and its height over that plane as z_j = -t_j^T S t_j / 2 + O(|t|^3), S the
// shape operator. The normal component of the estimate is then tr(S M_v) / (4 A_v) with
// M_v = sum_j w_j t_j t_j^T: it equals the mean curvature tr(S) / 2 for every S exactly when
// M_v = 4 A_v I, i.e. when the discrete Laplacian is exact for all quadratic functions of the tangent
// coordinates. Regular rings (equal angles, equal lengths, any valence >= 4) and uniform valence-6
// lattices satisfy it; the lattice strain around a 5-7 pair does not, and that strain is where most of
// the curvature error of a remeshed surface sits (Xu 2004 shows the estimate is not convergent on
// irregular meshes in general). The residual depends on the mesh alone, not on the surface's
// curvature, so the moves are the same for any f.
//
// The moves: Gauss-Seidel sweeps; each vertex takes one damped Gauss-Newton step in its tangent plane
// on the summed squared residuals of itself and its neighbours (forward differences), is projected
// back onto f = 0 by the caller's projection, and is kept only when that sum decreased and every
// incident triangle stays valid and above the angle floor (else the step is halved, up to 3 times).

#include <isopatch/geometry.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "remesh/editable_mesh.hpp"

namespace isopatch {

/// M_v / (4 A_v) - I in v's tangent plane (normal mesh.normals[v]) as (m11 - 1, m22 - 1, sqrt(2) m12),
/// so that its squared norm is the squared Frobenius norm; vertex `moved` taken at position p (pass
/// v's own position to evaluate the mesh as it is). A degenerate incident triangle or a zero area
/// gives a large residual. \pre v is alive and not on the boundary.
Eigen::Vector3d quadratic_exactness_residual(const EditableMesh& mesh, std::uint32_t v, std::uint32_t moved,
                                             const Vec3& p);

struct ExactnessMoveRules {
  /// Moves p (with normal n, both in/out) onto the surface by at most max_step; false on failure.
  std::function<bool(Vec3& p, Vec3& n, double max_step)> project;
  /// Whether triangle t stays valid when vertex v sits at (p, n) (orientation against the normals).
  std::function<bool(std::uint32_t t, std::uint32_t v, const Vec3& p, const Vec3& n)> triangle_valid;
  /// Target edge length near v: bounds a step to a fifth of it.
  std::function<double(std::uint32_t v)> size;
  /// A triangle's smallest angle (degrees) may not drop below min(its current one, angle_floor).
  double angle_floor = 20.0;
  /// Called before every sweep (may be empty); may throw to stop, e.g. on cancellation.
  std::function<void()> before_sweep;
};

/// Runs `sweeps` Gauss-Seidel sweeps over the free (alive, unlocked) vertices and returns the number
/// of moves kept. Each vertex keeps the tangent frame it had at the start of a sweep until the next.
/// \post within a sweep, every kept move lowered the residual sum of the moved vertex and its
/// neighbours (in those frames), so the sum over all free vertices did not rise; where the normals
/// are constant (a plane) that is also the sum of laplacian_exactness_energy. The connectivity is
/// unchanged, every kept position passed rules.project and rules.triangle_valid, and no smallest
/// angle fell below min(its value before the move, rules.angle_floor).
std::size_t improve_laplacian_exactness(EditableMesh& mesh, const ExactnessMoveRules& rules, int sweeps);

/// Sum of squared residuals over the free vertices (for tests and statistics).
double laplacian_exactness_energy(const EditableMesh& mesh);

}  // namespace isopatch
