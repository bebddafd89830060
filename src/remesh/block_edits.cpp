// Grouping of listed edges into the cubes of a grid, see block_edits.hpp.
#include "remesh/block_edits.hpp"

#include <cmath>
#include <limits>

namespace isopatch {
namespace {

/// The longest edge times this is the side of a cube: an edit touches the rings of its edge's ends
/// (within about two edges of the cube), so two cubes of one colour (one cube apart) never meet, and few
/// listed edges cross a face.
constexpr double kEditBlockEdges = 12.0;

/// Grid coordinates fit in 20 bits each, so a cube's key with its colour is one 64-bit word.
constexpr double kMaxEditCoordinate = 1048575.0;

}  // namespace

EdgeList edges_by_key(std::vector<KeyedEdge>&& keyed) {
  std::sort(keyed.begin(), keyed.end());
  EdgeList edges(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) edges[i] = keyed[i].second;
  keyed = {};
  return edges;
}

double edit_block_width(double longest_edge) {
  return kEditBlockEdges * longest_edge;
}

EdgeCubes edge_cubes(const EditableMesh& mesh, const EdgeList& work,
                     const std::vector<std::uint32_t>& pending, double width, double shift) {
  EdgeCubes cubes;
  const auto live = [&](std::uint32_t i) { return mesh.alive(work[i].first) && mesh.alive(work[i].second); };
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  for (const std::uint32_t i : pending)
    if (live(i)) lo = lo.cwiseMin(mesh.positions[work[i].first]).cwiseMin(mesh.positions[work[i].second]);
  // The key of the cube holding vertex v: its colour in the top bits, then its three coordinates
  // (clamped, so that a huge mesh with tiny edges still fits: its last cubes then grow).
  const auto key_of = [&](std::uint32_t v) {
    std::uint64_t key = 0, colour = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const auto c = static_cast<std::uint64_t>(std::clamp(
          std::floor((mesh.positions[v][axis] - lo[axis]) / width + shift), 0.0, kMaxEditCoordinate));
      key |= c << (20 * axis);
      colour |= (c & 1u) << axis;
    }
    return key | colour << 60;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(pending.size());
  for (const std::uint32_t i : pending) {
    if (!live(i)) {
      cubes.across.push_back(i);  // the edit skips it; it keeps its place in the list's order
      continue;
    }
    const std::uint64_t key = key_of(work[i].first);
    if (key == key_of(work[i].second))
      keyed.push_back({key, i});
    else
      cubes.across.push_back(i);
  }
  std::sort(keyed.begin(), keyed.end());
  cubes.order.resize(keyed.size());
  for (std::size_t j = 0; j < keyed.size(); ++j) {
    cubes.order[j] = keyed[j].second;
    if (j == 0 || keyed[j].first != keyed[j - 1].first)
      cubes.runs[keyed[j].first >> 60].push_back({j, j + 1});
    else
      cubes.runs[keyed[j].first >> 60].back().second = j + 1;
  }
  return cubes;
}

}  // namespace isopatch
