#pragma once
// Spatial blocks that let the valence flips of far-apart regions run in parallel with one result.
//
// The vertices are binned into axis-aligned cubes of side `width` (at least a few of the mesh's longest
// edges), and the cubes are coloured by the parities of their three grid coordinates: two cubes of one
// colour are at least one cube apart, so the flips confined to one cube (all four vertices of every
// flipped edge inside it) and everything they read (two rings around the cube's vertices) never meet
// those of another cube of the same colour. The cubes of a colour therefore run concurrently, each in
// its own fixed order: the same flips for any number of threads. A second grid shifted by half a cube
// gives the edges across the first grid's faces their turn.

#include <isopatch/geometry.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "remesh/editable_mesh.hpp"

namespace isopatch {

/// No block (a dead vertex slot).
inline constexpr std::uint32_t kNoBlock = 0xffffffffu;

struct FlipBlocks {
  Vec3 origin = Vec3::Zero();           ///< lower corner of the grid (before the shift)
  double width = 0.0;                   ///< side of a cube
  double shift = 0.0;                   ///< the grid's offset, as a fraction of width along every axis
  std::vector<std::uint32_t> block_of;  ///< per vertex slot: its cube, or kNoBlock
  std::vector<std::vector<std::uint32_t>> members;    ///< per cube: its live vertices, ascending
  std::array<std::vector<std::uint32_t>, 8> colours;  ///< the cubes of each colour

  /// Whether p lies within `margin` of a face of this grid's cubes.
  bool near_face(const Vec3& p, double margin) const;
};

/// The side of the cubes for `mesh`: a multiple of its longest live edge (0 for a mesh without edges).
double flip_block_width(const EditableMesh& mesh);

/// The live vertices of `mesh` binned into cubes of side `width` (> 0) whose grid starts at the lower
/// corner of the live vertices' bounds, moved by `shift` (in [0, 1)) times width along every axis.
/// Cubes are numbered in the order their first vertex appears (ascending vertex ids): deterministic.
FlipBlocks make_flip_blocks(const EditableMesh& mesh, double width, double shift);

}  // namespace isopatch
