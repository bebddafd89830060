// Small-angle repair of the surface-bound clean-up, see small_angle_repair.hpp.
#include "remesh/small_angle_repair.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

#include "remesh/cleanup_flips.hpp"
#include "remesh/edge_edits.hpp"

namespace isopatch::cleanup {

void repair_until_settled(RemeshRun& run) {
  for (int pass = 0; pass < 3; ++pass)
    if (repair_small_angles(run) == 0) break;
}

std::size_t repair_small_angles(RemeshRun& run) {
  run.check_cancel();
  std::size_t changes = 0;
  for (std::uint32_t t = 0; t < run.mesh.triangles.size(); ++t) {
    if (!run.mesh.triangle_alive[t]) continue;
    const Triangle tri = run.mesh.triangles[t];
    if (run.smallest_angle_cosine(tri) <= run.cos_repair) continue;
    int longest = 0, shortest = 0;
    double lmax = -1.0, lmin = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const double l =
          run.length(tri[static_cast<std::size_t>(i)], tri[static_cast<std::size_t>((i + 1) % 3)]);
      if (l > lmax) lmax = l, longest = i;
      if (l < lmin) lmin = l, shortest = i;
    }
    const std::uint32_t a = tri[static_cast<std::size_t>(longest)];
    const std::uint32_t b = tri[static_cast<std::size_t>((longest + 1) % 3)];
    if (const auto e = run.mesh.interior_edge(a, b);
        e && try_flip(run, *e, [](double before, double after) { return after < before; })) {
      ++changes;
      continue;
    }
    // Else collapse the shortest edge, or the next when the link, a fold or a fixed vertex refuses it.
    const int middle = 3 - longest - shortest;
    for (int i : {shortest, middle}) {
      const std::uint32_t c = tri[static_cast<std::size_t>(i)];
      const std::uint32_t d = tri[static_cast<std::size_t>((i + 1) % 3)];
      if (try_collapse(run, c, d, 2.0 * run.sizes.edge(c, d), true)) {
        ++changes;
        ++run.stats.collapses;
        break;
      }
    }
  }
  run.stats.repairs += changes;
  return changes;
}

}  // namespace isopatch::cleanup
