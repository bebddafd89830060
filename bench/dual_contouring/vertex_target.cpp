// The Dual Contouring grid resolution for a target vertex count (Ju, Losasso, Schaefer & Warren,
// "Dual contouring of Hermite data", SIGGRAPH 2002): vertices grow as N^2, so N is estimated from a
// first run and corrected. See vertex_target.hpp.
#include "vertex_target.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

namespace isopatch::bench {
namespace {

constexpr int kFirstCells = 16;  // the first run: cheap, yet enough to see most surfaces
constexpr int kCorrections = 3;  // at most this many runs after the first that found the surface,
                                 // and one more across the target

std::size_t distance(std::size_t count, std::size_t target) {
  return count > target ? count - target : target - count;
}

}  // namespace

DualContouringResult dual_contouring_for_vertices(const Surface& surface, const Box& box,
                                                  std::size_t vertices, DualContouringOptions options) {
  if (vertices == 0) throw InputError("dual contouring: the vertex target must be positive");
  int runs = 0;
  double seconds = 0.0;
  std::set<int> tried;
  auto run = [&](int cells) {
    options.cells = cells;
    tried.insert(cells);
    DualContouringResult r = dual_contouring(surface, box, options);
    ++runs;
    seconds += r.seconds;
    return r;
  };

  // A first run; finer ones while it finds nothing (a small or thin surface).
  DualContouringResult best = run(kFirstCells);
  while (best.mesh.vertex_count() == 0 && best.cells < kMaxSearchCells)
    best = run(std::min(2 * best.cells, kMaxSearchCells));
  if (best.mesh.vertex_count() == 0)
    throw InputError("dual contouring: no surface in the box on a grid of " +
                     std::to_string(kMaxSearchCells) + " cells");

  // Corrections: N * sqrt(target / count) from the latest run, until a resolution repeats.
  int cells = best.cells;
  std::size_t count = best.mesh.vertex_count();
  for (int correction = 0; correction < kCorrections && count != vertices; ++correction) {
    const double estimate = cells * std::sqrt(static_cast<double>(vertices) / static_cast<double>(count));
    const int next = std::clamp(static_cast<int>(std::lround(estimate)), 2, kMaxSearchCells);
    if (tried.contains(next)) break;
    DualContouringResult r = run(next);
    cells = next;
    count = r.mesh.vertex_count();
    if (count == 0) break;
    const std::size_t d = distance(count, vertices);
    const std::size_t best_d = distance(best.mesh.vertex_count(), vertices);
    if (d < best_d || (d == best_d && r.cells < best.cells)) best = std::move(r);
  }
  // The count grows with N: the neighbour of the best on the other side of the target, if untried,
  // may be closer.
  const int other = best.mesh.vertex_count() < vertices ? best.cells + 1 : best.cells - 1;
  if (best.mesh.vertex_count() != vertices && other >= 2 && other <= kMaxSearchCells &&
      !tried.contains(other)) {
    DualContouringResult r = run(other);
    if (distance(r.mesh.vertex_count(), vertices) < distance(best.mesh.vertex_count(), vertices))
      best = std::move(r);
  }
  best.search_runs = runs;
  best.search_seconds = seconds;
  return best;
}

}  // namespace isopatch::bench
