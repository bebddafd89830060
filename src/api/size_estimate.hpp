#pragma once
// The output's size, estimated before any meshing, so that a request beyond the vertex budget is
// refused at once with the estimate in the message rather than after minutes of work.

#include <isopatch/geometry.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <cstdint>

namespace isopatch {

/// Cells of the coarse Marching Cubes grid along the longest box side that measures the area.
inline constexpr int kEstimateGrid = 32;

/// About how many vertices a projection mesh of `surface` in `box` with `settings`' target edge length
/// h has: a triangulation of area A by equilateral triangles of side h has 2 A / (sqrt(3) h^2) vertices,
/// with A measured on a Marching Cubes mesh of a kEstimateGrid grid (so features smaller than its cells
/// are missed, and varying sizes, which are at most h, make the estimate a lower bound).
/// \throw EvaluationError when f is not finite at a grid point.
/// `evaluations`, when given, receives the evaluations of f it made.
double estimated_vertices(const Surface& surface, const Settings& settings, const Box& box,
                          std::uint64_t* evaluations = nullptr);

/// When settings.max_vertices is set: throws LimitError("max_vertices") naming the estimate when it
/// exceeds the budget. Costs about kEstimateGrid^3 evaluations of f (a few milliseconds). Returns the
/// evaluations it made (0 without a budget), for the run's statistics.
std::uint64_t check_estimated_size(const Surface& surface, const Settings& settings, const Box& box);

}  // namespace isopatch
