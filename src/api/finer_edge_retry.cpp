// A crease path's failure at the edge's scale retried at half the edge (finer_edge_retry.hpp).
#include "api/finer_edge_retry.hpp"

#include <isopatch/error.hpp>

#include <utility>

namespace isopatch {

namespace {

/// Retries nested at most this deep: half the edge, then a quarter.
constexpr int kMostHalvings = 2;

/// Retries running on this thread, nested (the sub-meshes of the crease paths, a sheet's walls or the
/// operands of a shape apart, run on the calling thread).
thread_local int retries_running = 0;

struct RetryGuard {
  RetryGuard() { ++retries_running; }
  ~RetryGuard() { --retries_running; }
  RetryGuard(const RetryGuard&) = delete;
  RetryGuard& operator=(const RetryGuard&) = delete;
};

}  // namespace

bool finer_edge_may_help(const std::string& failure) {
  const auto has = [&failure](const char* words) { return failure.find(words) != std::string::npos; };
  return has("than an edge") || has("narrower") || has("too short");
}

std::optional<Mesh> mesh_at_half_edge(const Surface& surface, const Settings& settings, MeshStats* stats,
                                      const std::string& failure, double edge, const WallMesher& mesh) {
  if (retries_running >= kMostHalvings || !finer_edge_may_help(failure) || settings.max_error ||
      settings.size_field)
    return std::nullopt;
  const RetryGuard guard;
  Settings finer = settings;
  finer.edge_length = 0.5 * edge;
  finer.creases = Creases::Exact;
  MeshStats own = stats ? *stats : MeshStats{};
  try {
    Mesh out = mesh(surface, finer, stats ? &own : nullptr);
    if (stats) {
      *stats = std::move(own);
      // A retry inside this one (a quarter of the edge) has set the finer length already.
      if (!(stats->warnings.creases_finer_edge > 0.0)) stats->warnings.creases_finer_edge = 0.5 * edge;
      stats->warnings.crease_failure = failure;
    }
    return out;
  } catch (const CreaseError&) {
    return std::nullopt;
  } catch (const LimitError& e) {
    if (e.setting() != "max_vertices") throw;
    return std::nullopt;
  }
}

}  // namespace isopatch
