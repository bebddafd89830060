#pragma once
// The last step of the refinement: single vertices moved to raise the smallest angle of the triangles
// around them, where a triangle stays under a floor after the relaxation sweeps. Uniform-Laplacian
// moves even out a lattice but do not aim at its worst angle (more of them lowered it on the
// tanglecube, docs/algorithms.md 8.5); this is a pattern search on the smallest angle of a vertex's fan
// itself: candidate points around the vertex in its tangent plane, each put on f = 0, the best kept when
// it raises that angle and leaves every triangle of the fan facing the surface. The vertices are found
// by two parallel scans of the triangles and then visited in ascending order, one after the other,
// each seeing the moves before it, so the result does not depend on threads; the work is a few dozen
// landings per vertex of a triangle under the floor, a small share of the mesh.

#include <isopatch/mesh.hpp>

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "refine/batched_newton.hpp"
#include "refine/lattice_relaxation.hpp"

namespace isopatch::refine {

struct AngleRepairInput {
  const std::vector<Motion>& motion;                  ///< only Free vertices move
  std::span<const Sampler* const> functions;          ///< the functions the vertices lie on
  const std::vector<std::uint32_t>& vertex_function;  ///< per vertex, its function (empty: the first)
  const BoundaryPlanes& planes;                       ///< (no free vertex stays on one)
  const NewtonLimits& limits;
};

/// Raises the smallest angle around the free vertices of the triangles of `mesh` under `floor` degrees,
/// in at most `rounds` passes (see the file comment); `normals` (unit grad f per vertex) are kept up
/// to date. Returns the moves made.
/// \throw EvaluationError when f or grad f is not finite where a candidate lands.
std::size_t repair_small_angles(Mesh& mesh, std::vector<Eigen::Vector3f>& normals, const AngleRepairInput& in,
                                double floor, int rounds);

}  // namespace isopatch::refine
