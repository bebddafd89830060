// Spatial blocks for parallel valence flips, see flip_blocks.hpp.
#include "remesh/flip_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace isopatch {
namespace {

/// The longest edge times this is the side of a cube: flips read up to two rings around a cube's
/// vertices, so two cubes of one colour (one cube apart) stay well clear of each other, and the chains
/// of glide flips have room to travel before they meet a face.
constexpr double kBlockEdges = 12.0;

/// Grid coordinates fit in 21 bits each, so a cube's key is one 64-bit word.
constexpr double kMaxCoordinate = 2097151.0;

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
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v)
    if (mesh.alive(v)) lo = lo.cwiseMin(mesh.positions[v]);
  blocks.origin = lo;
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v) {
    if (!mesh.alive(v)) continue;
    std::uint64_t key = 0;
    unsigned colour = 0;
    for (int axis = 0; axis < 3; ++axis) {
      // Clamped so that a huge mesh with tiny edges still fits the key (its cubes then grow).
      const double u =
          std::clamp(std::floor((mesh.positions[v][axis] - lo[axis]) / width + shift), 0.0, kMaxCoordinate);
      const auto coordinate = static_cast<std::uint64_t>(u);
      key |= coordinate << (21 * axis);
      colour |= static_cast<unsigned>(coordinate & 1u) << axis;
    }
    const auto [it, added] = index.try_emplace(key, static_cast<std::uint32_t>(blocks.members.size()));
    if (added) {
      blocks.members.emplace_back();
      blocks.colours[colour].push_back(it->second);
    }
    blocks.block_of[v] = it->second;
    blocks.members[it->second].push_back(v);
  }
  return blocks;
}

}  // namespace isopatch
