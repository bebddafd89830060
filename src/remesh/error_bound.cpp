// Error bound of the surface-bound clean-up, see error_bound.hpp.
#include "remesh/error_bound.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "remesh/edge_edits.hpp"
#include "remesh/small_angle_repair.hpp"
#include "remesh/triangle_measures.hpp"

namespace isopatch::cleanup {

std::size_t enforce_error_bound(RemeshRun& run) {
  const double eps = *run.settings.sizes.max_error;
  for (int round = 0;; ++round) {
    run.check_cancel();
    std::size_t beyond = 0;
    std::vector<std::pair<double, std::pair<std::uint32_t, std::uint32_t>>> work;
    for (std::uint32_t t = 0; t < run.mesh.triangles.size(); ++t) {
      if (!run.mesh.triangle_alive[t]) continue;
      const double distance = centroid_distance(run.f, run.mesh.positions, run.mesh.triangles[t]);
      beyond += distance > eps;
      if (!(distance > kBoundMargin * eps)) continue;
      const auto edge = longest_edge(run.mesh.positions, run.mesh.triangles[t]);
      work.push_back({-run.length(edge.first, edge.second), edge});
    }
    if (work.empty() || round == kBoundRounds) return beyond;
    std::sort(work.begin(), work.end());
    work.erase(std::unique(work.begin(), work.end()), work.end());
    const std::size_t splits = split_listed(run, edges_by_key(std::move(work)), run.mesh.longest_edge());
    if (splits == 0) return beyond;
    run.sizes.update(run.mesh);
    repair_until_settled(run);
  }
}

}  // namespace isopatch::cleanup
