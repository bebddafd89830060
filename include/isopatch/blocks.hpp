#pragma once
/// \file blocks.hpp
/// A surface meshed as blocks refined apart (docs/distributed.md): one coarse base of good quality
/// (the multiresolution base, docs/algorithms.md 8), its triangles cut into blocks along a space-filling
/// curve, every block refined by the same level on its own (on another process or machine), and the
/// blocks' pieces put together by global vertex numbers. The rule that makes the seams exact: a point
/// on a base edge is made from that edge alone (its two ends, their normals from f, and f), and a base
/// edge between two blocks is held where it lands, so both blocks make the same point to the bit and
/// either one's copy can be written. The numbers of the output's vertices are known before any block is
/// refined (a prefix sum of counts the base gives), so every block writes its vertices and triangles in
/// final numbers and the merged mesh does not depend on the order blocks finish.
///
/// Follows the multiresolution refinement (Lee et al. 2000, Guskov et al. 2000; refine/refine_mesh.hpp)
/// on Sipos & Salvi 2021's projection base, and the global-id scheme of VTK's distributed data (ghost
/// cells, global point ids) in its simplest form: ownership by the lowest block beside a shared item.

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/mesh_stats.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace isopatch {

class CompositeModel;  // isopatch/composite_mesh.hpp

/// What a composite's base is made of (all empty for a surface of one function): the patch of every
/// base triangle, and per curve of the composite the segments the base sampled it with and its base
/// vertices from its start to its end (segments + 1 of them, or none for a curve no patch uses). A
/// refined base edge on a curve takes the curve's own points, sampled at `level` times its segments
/// from the curve alone, so the two blocks beside it make them to the bit.
struct BasePatches {
  std::vector<std::uint32_t> triangle_patch;
  std::vector<int> curve_segments;
  std::vector<std::vector<std::uint32_t>> curve_vertices;
};

/// The base a blocked run refines.
struct BlockBase {
  Mesh base;            ///< the coarse mesh (projection and clean-up at `level` times the target edge)
  int level = 1;        ///< every base edge is cut into `level` segments
  BasePatches patches;  ///< a composite's patches and curves (empty for one function)
};

/// The base of `surface` for `settings` and the level it is refined by, chosen as mesh_surface() chooses
/// them for the multiresolution mesh: settings.refine when given, else the automatic level from a
/// coarse estimate of the curvature, checked on the base's own curvature. The guard and angle checks of
/// the refinement itself come later, per block (BlockMesh::kept): the caller halves the level
/// (settings.refine = level / 2) when a block is not kept.
/// \throw SettingError for the Marching Cubes method, or ("creases") when the surface is a formula meshed
///        along exact creases (creased_pieces() gives the pieces blocks mesh it with); the errors of
///        mesh_surface().
BlockBase block_base(const Surface& surface, const Settings& settings);

/// The base of a composite surface (.ipatch: I-patches, setback vertex blends) for `settings` and its
/// level, as mesh_composite() chooses them along the composite's curves: its projection mesh at `level`
/// times the target edge (every curve sampled once and shared by the patches beside it), the automatic
/// level checked on the base's curvature patch by patch; BlockBase::patches filled.
/// \throw SettingError for the Marching Cubes method, a frame, a region or given cells (a blocked
///        composite is meshed along its curves), or the octree's settings (as mesh_composite()); the
///        errors of mesh_composite() (EvaluationError, LimitError for budgets).
BlockBase block_base(const CompositeModel& model, const Settings& settings);

/// How a base is cut into blocks and how the output is numbered.
struct BlockPlan {
  int level = 1;
  int blocks = 1;
  std::vector<std::uint32_t> triangle_block;  ///< per base triangle, its block
  /// Per block: the first output vertex number it owns and how many it owns, and its first output
  /// triangle and triangle count (k^2 per base triangle). A block owns the base vertices and base edges
  /// of which it is the lowest block among the triangles around them, and the inner points of its own
  /// triangles; its vertices are numbered in that order (base vertices ascending, then the k - 1 points
  /// of each owned edge, edges ascending, then the inner points of its triangles, ascending).
  std::vector<std::uint64_t> first_vertex, vertex_count, first_triangle, triangle_count;
  /// Per block: the base vertices and the base edges it owns.
  std::vector<std::uint64_t> owned_base_vertices, owned_edges;
  std::uint64_t vertices = 0;   ///< in the whole output
  std::uint64_t triangles = 0;  ///< in the whole output
  /// The output's number of every point the refinement makes, by what it is made from: per base vertex
  /// its number; per base edge (edge_ends: its lower and higher base vertex, in ascending order) the
  /// number of its first point (the k - 1 points follow from the lower end) and whether it lies between
  /// two blocks (a seam); per base triangle the number of its first inner point (the rest follow).
  std::vector<std::uint64_t> vertex_number;
  std::vector<std::array<std::uint32_t, 2>> edge_ends;
  std::vector<std::uint64_t> edge_first_number;
  std::vector<std::uint8_t> edge_between_blocks;
  std::vector<std::uint64_t> triangle_first_inner;
};

/// Cuts `base` into `blocks` blocks of about equal numbers of triangles, contiguous along the Morton
/// curve of the triangles' centroids in the base's bounding box, and numbers the output of refinement
/// by `level`. A composite's base (`patches` given) is cut patch by patch: its triangles ordered by
/// patch, each cut moved to the nearest patch boundary within a quarter of a block (a seam along a curve
/// takes the curve's own points, held in one process too, so such a seam costs nothing), and a corner's
/// triangles in one patch never cut apart (a seam through a corner would hold the refined triangle
/// between a curve and the seam as it lands: 11 to 16 degrees on the blend examples where one process
/// relaxes it to 25). Depends on the base's bytes, `level`, `blocks` and `patches` alone (every worker
/// can recompute it).
/// \throw InputError when the base has no triangles, blocks < 1 or more than the base's triangles (or
///        so many that a block would be empty), level is outside 1..32, or `patches` names another
///        number of triangles or a vertex the base does not have; LimitError when the output would need
///        more than 2^63 numbers.
BlockPlan plan_blocks(const Mesh& base, int level, int blocks, const BasePatches& patches = {});

/// One block of the output, in the output's numbers.
struct BlockMesh {
  int block = 0;
  /// The vertices the block owns, numbers first_vertex .. first_vertex + count - 1 in order.
  std::vector<Vec3> positions;
  /// The block's triangles in output numbers (k^2 per base triangle, base triangles in ascending order).
  std::vector<std::array<std::uint64_t, 3>> triangles;
  /// The vertices it uses but another block owns (on its seams), with its own copies of them: equal to
  /// the owner's bit for bit (assemble_blocks() checks).
  std::vector<std::uint64_t> seam_ids;
  std::vector<Vec3> seam_positions;
  /// Points or triangles that failed the refinement's guard (then positions and triangles are empty).
  std::size_t failed_points = 0;
  double smallest_angle = 0.0;  ///< degrees, over the block's triangles
  /// Whether the refinement is kept as one process would keep it: no failed point and, at the automatic
  /// level, a smallest angle of at least 20 degrees. When a block is not, the caller halves the level.
  bool kept = false;
  /// The block's vertices within one base edge of a seam (the band where it could not relax across).
  std::size_t seam_band_vertices = 0;
};

/// Refines block `block` of `plan` on `surface` with the preset of `settings` (the multiresolution
/// refinement's sweeps and angle repair; the box and region cut it): base edges between this block and
/// another are landed from the edge alone and held. The same bytes for any thread count and on any
/// machine with the same build.
/// Uses the plan's numbers: nothing of the whole base is computed again.
/// \pre plan == plan_blocks(base, level, blocks) for this base.
/// \throw InputError for a block outside 0..blocks-1 or a plan that does not fit the base; the errors
///        of the refinement (LimitError for settings.max_vertices or cancel, EvaluationError).
BlockMesh refine_block(const Surface& surface, const Settings& settings, const Mesh& base,
                       const BlockPlan& plan, int block);

/// refine_block() for a composite's base (block_base(CompositeModel, ...)): every point lands on, and
/// relaxes on, its own patch's function; a base edge on a curve takes the curve's own points (the same
/// in every block); a curve vertex's normal is its patch's in the whole base (the lowest-numbered base
/// triangle's), so a seam edge that ends on a curve starts the same in both blocks. BlockMesh::kept as
/// one process keeps a composite's level (also within half a degree of the whole base's smallest angle,
/// or at least 25 degrees).
/// \pre plan == plan_blocks(base, level, blocks) and `patches` is the BlockBase's for this base.
/// \throw InputError when `patches` does not describe a base of the composite, and as refine_block().
BlockMesh refine_block(const CompositeModel& model, const BasePatches& patches, const Settings& settings,
                       const Mesh& base, const BlockPlan& plan, int block);

/// A formula with exact creases (a CSG shape, docs/creases.md) as blocks mesh it: the composite of its
/// pieces, bounded by its creases and seams, and the face functions the last angle repair keeps its
/// vertices on. Opaque; made by creased_pieces().
struct CreasedPieces;

/// The crease analysis of `surface` with `settings`, as one process makes it (src/csg: the same
/// settings give the same analysis, bit for bit, in every process), or null when the surface is meshed
/// as a smooth one: creases off, another method, a region, frame or given cells, not a formula, no
/// crease in the box, or a crease that leaves the box (one process then meshes it smooth and warns).
/// \throw CreaseError for a shape whose creases cannot be meshed (docs/creases.md); EvaluationError.
std::shared_ptr<const CreasedPieces> creased_pieces(const Surface& surface, const Settings& settings);

/// The base of a formula with creases and its level, as mesh_surface() makes them along its creases:
/// the composite of its pieces meshed along its creases and seams (BlockBase::patches filled).
/// \pre `pieces` is creased_pieces(surface, settings) for these settings.
/// \throw as block_base(CompositeModel, ...) but without its checks of the settings (the formula's).
BlockBase block_base(const CreasedPieces& pieces, const Settings& settings);

/// refine_block() for a formula with creases: as a composite's block, then the crease angle repair of
/// one process (triangles under 27 degrees, vertices moved on their faces or along their crease) with
/// the block's seam vertices held. BlockMesh::kept on the angles the repair leaves, as one process
/// judges a level.
/// \throw as refine_block(CompositeModel, ...).
BlockMesh refine_block(const CreasedPieces& pieces, const BasePatches& patches, const Settings& settings,
                       const Mesh& base, const BlockPlan& plan, int block);

/// A lattice capped or shelled by a polyhedron (docs/lattices.md), or a sheet whose walls are, as blocks
/// mesh it: its parts, each a smooth surface cut open by planes and closed by planar caps. Every part's
/// cut is one or more surfaces (a sheet's walls), each refined in blocks like any surface with the
/// planes as its region; the caps are made afterwards on one machine. Opaque; made by capped_pieces().
struct CappedPieces;

/// The parts of `surface` as one process meshes it along its caps (a capped solid: one; a shell: the
/// outer polyhedron's caps and the hollows; a sheet: its walls', in order), or null when one process
/// would not mesh it that way (not a formula of that form, creases off, another method, a region or
/// cells given, g with creases of its own). Every process makes the same parts from the same settings.
/// \throw SettingError for a frame (blocks take none); the errors of the crease analysis of g.
std::shared_ptr<const CappedPieces> capped_pieces(const Surface& surface, const Settings& settings);

/// How many parts `pieces` has.
std::size_t capped_part_count(const CappedPieces& pieces);

/// The cut surfaces to mesh in blocks, in order, as the part each belongs to: a part's cut is its
/// smooth surface, or that surface's two walls when it is a sheet (four for a sheet of a sheet), in the
/// order one process appends them; a shell's outer polyhedron has none (only caps).
std::vector<std::size_t> capped_cut_parts(const CappedPieces& pieces);

/// The base of cut `cut` (an index into capped_cut_parts()) and its level, as block_base(Surface) makes
/// it with the cut's settings (the part's planes as the region; the box grown where the polyhedron
/// reaches it).
/// \throw InputError for a cut out of range; LimitError when the caps would exceed
///        settings.max_vertices; the errors of block_base(Surface, ...).
BlockBase block_base(const CappedPieces& pieces, std::size_t cut, const Settings& settings);

/// refine_block() for cut `cut` (the cut's settings).
/// \throw as block_base(CappedPieces, ...) and refine_block(Surface, ...).
BlockMesh refine_block(const CappedPieces& pieces, std::size_t cut, const Settings& settings,
                       const Mesh& base, const BlockPlan& plan, int block);

/// The whole part: every part's cut (the meshes of its cut surfaces, `cuts`, one per entry of
/// capped_cut_parts(), each assembled from its blocks, appended in order) closed by its caps, its
/// narrow corners flipped and the last angle repair run, as one process closes its cut; the parts
/// appended in order (a shell's hollows turned inside out). `stats` (optional) gets MeshStats::creases
/// (caps, crease vertices) and the stage "caps".
/// \throw InputError when `cuts` does not have one mesh per cut; CreaseError when a part's result is not
///        the closed 2-manifold expected (as one process).
Mesh close_capped(const CappedPieces& pieces, std::vector<Mesh> cuts, const Settings& settings,
                  MeshStats* stats = nullptr);

/// The whole output from every block's mesh (in any order; each block once), checking that every seam
/// copy equals its owner's vertex bit for bit.
/// \throw InputError when a block is missing, repeated, does not match the plan's counts, or a seam copy
///        differs from its owner (the blocks were made from different bases or builds); LimitError when
///        the output has more than 2^32 - 1 vertices (Mesh numbers are 32-bit).
Mesh assemble_blocks(const BlockPlan& plan, std::span<const BlockMesh> blocks);

}  // namespace isopatch
