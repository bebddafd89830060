#pragma once
// One block of a blocked base as a mesh of its own, and its refinement put in the output's numbers
// (isopatch/blocks.hpp): shared by the blocks of one function and of a composite's patches.

#include <isopatch/blocks.hpp>
#include <isopatch/composite_mesh.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "refine/refine_mesh.hpp"

namespace isopatch::blocks {

/// A block's triangles as a mesh of their own, its vertices numbered in the base's order (so every edge
/// runs from its lower to its higher end in both numberings and its points are made the same way).
struct BlockPiece {
  Mesh mesh;
  std::vector<std::uint32_t> triangles;  ///< base triangle of each local triangle, ascending
  std::vector<std::uint32_t> vertices;   ///< base vertex of each local vertex, ascending
};

/// Block `block` of `plan` cut out of `base`.
/// \throw InputError for a block outside 0..plan.blocks-1 or a plan that does not fit the base.
BlockPiece block_piece(const Mesh& base, const BlockPlan& plan, int block);

/// Refines a piece's mesh with the given parameters (refine_mesh or refine_pieces on its functions).
using PieceRefiner =
    std::function<refine::RefineResult(const Mesh& piece, const refine::RefineParams& params)>;

/// A last pass over a refined block (the crease angle repair): may move the vertices whose flag in
/// `held` is 0 (held: the block's seam vertices, which the blocks across make too), not the topology.
using PieceFinisher = std::function<void(Mesh& refined, const std::vector<std::uint8_t>& held)>;

/// Refines `piece` (block `block` of `plan` on `base`) with `refine` and the preset of `settings` in
/// `box`, its seams with other blocks landed from the edge alone and held, runs `finish` (when given)
/// on the refined block, and gives the block in the output's numbers. The block is kept as
/// refinement_kept() keeps it, on the angles after `finish`; with `base_smallest_angle` (a composite's
/// base) as the overload that also asks for the base's angles.
/// \throw as refine_block().
BlockMesh refine_piece(const Settings& settings, const Box& box, const Mesh& base, const BlockPlan& plan,
                       int block, const BlockPiece& piece, const PieceRefiner& refine,
                       std::optional<double> base_smallest_angle, const PieceFinisher& finish = {});

/// \throw SettingError for settings no blocked run keeps (another method than projection, a frame);
///        the errors of Settings::validate().
void check_blocked_settings(const Settings& settings);

/// check_blocked_settings() and the settings tiles by planes do not take either (a region or cells, an
/// error bound or a size field). \throw SettingError naming the first.
void check_tiled_settings(const Settings& settings);

/// A composite's base for blocks, as block_base(CompositeModel) makes it but without its checks of the
/// settings (a formula's creases are meshed with the settings of the formula).
BlockBase composite_block_base(const CompositeModel& model, const Settings& settings);

/// refine_block(CompositeModel, ...) with a last pass `finish` (may be empty).
BlockMesh refine_composite_block(const CompositeModel& model, const BasePatches& patches,
                                 const Settings& settings, const Mesh& base, const BlockPlan& plan, int block,
                                 const PieceFinisher& finish);

}  // namespace isopatch::blocks
