#pragma once
// The closed curves where two smooth surfaces a = 0 and b = 0 meet (the crease of max(a, b)), traced on
// a mesh of a: marching triangles on the values of b at its vertices give loops of edge crossings, each
// put on both surfaces by minimum-norm Newton steps (surface/curve_point.hpp), then resampled at even
// arc length. The loops are the held boundary that the two faces of a lattice cut by a curved solid
// share (curved_cut.hpp). docs/lattices.md.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <vector>

namespace isopatch {

/// One closed crease curve, its points in the direction of grad a x grad b (a's side where b < 0 on
/// the left, seen from outside a); the last point joins the first.
struct CreaseLoop {
  std::vector<Vec3> points;
};

/// The crease loops of a and b on `mesh_a` (a mesh of a = 0, closed where the crease runs), each
/// resampled at about `edge` (at least 3 points) and every point on both surfaces to `tolerance`.
/// \throw CreaseError naming the place when the crease reaches the mesh's boundary (it leaves the mesh's
///        box), the surfaces meet tangentially (no curve to settle on), or a resampled loop folds;
///        EvaluationError where a or b is not finite.
std::vector<CreaseLoop> trace_crease_loops(const Mesh& mesh_a, const Surface& a, const Surface& b,
                                           double edge, double tolerance);

}  // namespace isopatch
