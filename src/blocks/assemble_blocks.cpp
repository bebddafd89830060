// The whole output from its blocks (blocks.hpp).
#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>

#include <cstring>
#include <limits>
#include <string>

namespace isopatch {
namespace {

void check_block(const BlockPlan& plan, const BlockMesh& block, std::vector<std::uint8_t>& seen) {
  const std::string name = "block " + std::to_string(block.block);
  if (block.block < 0 || block.block >= plan.blocks)
    throw InputError(name + " is not a block of the plan", "block");
  const auto b = static_cast<std::size_t>(block.block);
  if (seen[b]++) throw InputError(name + " is given twice", "block");
  if (block.failed_points > 0) throw InputError(name + " failed the refinement's guard", "block");
  if (block.positions.size() != plan.vertex_count[b] || block.triangles.size() != plan.triangle_count[b])
    throw InputError(name + " does not have the plan's counts (made from another base?)", "block");
  if (block.seam_ids.size() != block.seam_positions.size())
    throw InputError(name + " has seam numbers without positions", "block");
}

}  // namespace

Mesh assemble_blocks(const BlockPlan& plan, std::span<const BlockMesh> blocks) {
  if (plan.vertices >= std::numeric_limits<std::uint32_t>::max())
    throw LimitError("the output has " + std::to_string(plan.vertices) +
                         " vertices, more than one mesh numbers with 32 bits: write the blocks apart",
                     "tiles");
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(plan.blocks), 0);
  for (const BlockMesh& block : blocks) check_block(plan, block, seen);
  if (blocks.size() != static_cast<std::size_t>(plan.blocks))
    throw InputError(std::to_string(plan.blocks - static_cast<int>(blocks.size())) + " of the plan's " +
                         std::to_string(plan.blocks) + " blocks are missing",
                     "block");
  Mesh mesh;
  mesh.positions.resize(plan.vertices);
  mesh.triangles.resize(plan.triangles);
  for (const BlockMesh& block : blocks) {
    const auto b = static_cast<std::size_t>(block.block);
    std::copy(block.positions.begin(), block.positions.end(),
              mesh.positions.begin() + static_cast<std::ptrdiff_t>(plan.first_vertex[b]));
    for (std::size_t t = 0; t < block.triangles.size(); ++t) {
      Triangle& out = mesh.triangles[plan.first_triangle[b] + t];
      for (int c = 0; c < 3; ++c) {
        const std::uint64_t v = block.triangles[t][static_cast<std::size_t>(c)];
        if (v >= plan.vertices)
          throw InputError("block " + std::to_string(block.block) + " names a vertex beyond the output",
                           "block");
        out[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(v);
      }
    }
  }
  for (const BlockMesh& block : blocks)
    for (std::size_t i = 0; i < block.seam_ids.size(); ++i) {
      const std::uint64_t v = block.seam_ids[i];
      if (v >= plan.vertices ||
          std::memcmp(mesh.positions[v].data(), block.seam_positions[i].data(), sizeof(Vec3)) != 0)
        throw InputError("block " + std::to_string(block.block) + "'s copy of seam vertex " +
                             std::to_string(v) +
                             " differs from its owner's (blocks made from different bases or builds)",
                         "block");
    }
  return mesh;
}

}  // namespace isopatch
