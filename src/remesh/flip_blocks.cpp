// Spatial blocks for parallel valence flips, see flip_blocks.hpp.
#include "remesh/flip_blocks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace isopatch {
namespace {

/// The longest edge times this is the side of a cube: flips read up to two rings around a cube's
/// vertices, so two cubes of one colour (one cube apart) stay well clear of each other, and the chains
/// of glide flips have room to travel before they meet a face.
constexpr double kBlockEdges = 12.0;

/// Grid coordinates fit in 21 bits each, so a cube's key is one 64-bit word.
constexpr double kMaxCoordinate = 2097151.0;

/// Grids of at most this many cubes (a table of 16 MB; a dozen-edge cube makes far fewer) are indexed by
/// a dense table, larger ones by a hash map.
constexpr std::uint64_t kMaxDenseCubes = std::uint64_t{1} << 22;

}  // namespace

bool FlipBlocks::near_face(const Vec3& p, double margin) const {
  for (int axis = 0; axis < 3; ++axis) {
    const double u = (p[axis] - origin[axis]) / width + shift;
    const double distance = std::min(u - std::floor(u), std::ceil(u) - u) * width;
    if (distance < margin) return true;
  }
  return false;
}

double flip_block_width(const EditableMesh& mesh) {
  return kBlockEdges * mesh.longest_edge();
}

FlipBlocks make_flip_blocks(const EditableMesh& mesh, double width, double shift) {
  FlipBlocks blocks;
  blocks.width = width;
  blocks.shift = shift;
  blocks.block_of.assign(mesh.vertex_slots(), kNoBlock);
  Vec3 lo = Vec3::Constant(INFINITY);
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v)
    if (mesh.alive(v)) lo = lo.cwiseMin(mesh.positions[v]);
  blocks.origin = lo;
  // Grid coordinates of a vertex, clamped so that a huge mesh with tiny edges still fits the key (its
  // cubes then grow); and the grid's extent.
  const auto cell_of = [&](std::uint32_t v) {
    std::array<std::uint32_t, 3> c{};
    for (int axis = 0; axis < 3; ++axis)
      c[static_cast<std::size_t>(axis)] = static_cast<std::uint32_t>(
          std::clamp(std::floor((mesh.positions[v][axis] - lo[axis]) / width + shift), 0.0, kMaxCoordinate));
    return c;
  };
  std::array<std::uint64_t, 3> extent{1, 1, 1};
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v) {
    if (!mesh.alive(v)) continue;
    const auto c = cell_of(v);
    for (std::size_t k = 0; k < 3; ++k)
      extent[k] = std::max<std::uint64_t>(extent[k], c[k] + std::uint64_t{1});
  }
  // Cube ids by first appearance: a dense table when the grid is small (the usual case: the cubes are
  // a dozen edges wide), else a hash map of 63-bit keys.
  const std::uint64_t cubes = extent[0] * extent[1] * extent[2];
  const bool dense = extent[0] <= kMaxDenseCubes && extent[1] <= kMaxDenseCubes &&
                     extent[2] <= kMaxDenseCubes && cubes <= kMaxDenseCubes;
  std::vector<std::uint32_t> table(dense ? cubes : 0, kNoBlock);
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v) {
    if (!mesh.alive(v)) continue;
    const auto c = cell_of(v);
    const unsigned colour = (c[0] & 1u) | (c[1] & 1u) << 1 | (c[2] & 1u) << 2;
    const auto next = static_cast<std::uint32_t>(blocks.members.size());
    std::uint32_t id = next;
    if (dense) {
      std::uint32_t& slot = table[(std::uint64_t{c[2]} * extent[1] + c[1]) * extent[0] + c[0]];
      if (slot == kNoBlock) slot = next;
      id = slot;
    } else {
      const std::uint64_t key = std::uint64_t{c[0]} | std::uint64_t{c[1]} << 21 | std::uint64_t{c[2]} << 42;
      id = index.try_emplace(key, next).first->second;
    }
    if (id == next) {
      blocks.members.emplace_back();
      blocks.colours[colour].push_back(id);
    }
    blocks.block_of[v] = id;
    blocks.members[id].push_back(v);
  }
  return blocks;
}

}  // namespace isopatch
