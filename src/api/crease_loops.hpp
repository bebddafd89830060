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

/// One crease curve, its points in the direction of grad a x grad b (a's side where b < 0 on the left,
/// seen from outside a). Closed: the last point joins the first. Open (a crease cut by the box): an arc
/// whose first and last points lie on faces of the box, exactly (the coordinate of that face), and on
/// a = b = 0.
struct CreaseLoop {
  std::vector<Vec3> points;
  bool closed = true;
};

/// The crease curves of a and b on `mesh_a` (a mesh of a = 0), each resampled at about `edge` (a closed
/// loop at least 3 points, an arc at least 2 segments) and every point on both surfaces to `tolerance`;
/// the closed loops first, then the arcs. Without `open_at`, `mesh_a` must be closed where the crease
/// runs; with it (the box `mesh_a` was meshed in, its boundary on the box's faces), a crease reaching the
/// mesh's boundary is an arc ending where a = b = 0 meets that face of the box.
/// \throw CreaseError naming the place when the crease reaches the mesh's boundary without `open_at` (it
///        leaves the mesh's box) or at an edge of the box, or a resampled curve folds;
///        ShapeNotManifoldError (a CreaseError) where the surfaces meet tangentially (no curve to settle
///        on: the shape is no 2-manifold there); EvaluationError where a or b is not finite.
std::vector<CreaseLoop> trace_crease_loops(const Mesh& mesh_a, const Surface& a, const Surface& b,
                                           double edge, double tolerance, const Box* open_at = nullptr);

}  // namespace isopatch
