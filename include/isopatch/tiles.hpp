#pragma once
/// \file tiles.hpp
/// A surface meshed as tiles of its box cut by planes (docs/distributed.md, "Tiles by planes"): for
/// surfaces whose base (blocks.hpp) is itself too large for one machine. The box is cut by a lattice of
/// axis planes into tiles. First, once per face of that lattice, the curves where f = 0 meets the face
/// are traced and sampled at the base's edge length (face_curves()): data that both tiles beside the
/// face read, so neither computes its own seam. Each tile then makes its base on its own (the
/// projection mesher and the clean-up in the tile's box, its cut replaced by the faces' curves and held
/// there: tile_base()), refines it, its boundary edges landed on their face's curve from the edge alone
/// and held (refine_tile()), and the tiles are put together by their shared vertices, equal bit for bit
/// (assemble_tiles()).
///
/// Follows the multiresolution refinement (Lee et al. 2000, Guskov et al. 2000; refine/refine_mesh.hpp)
/// on Sipos & Salvi 2021's projection base, and the rule of tiled meshers that make seams exact (the
/// shared face's data computed once and read by both sides; a tile never moves its seam vertices).

#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/surface.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace isopatch {

/// The domain box cut into counts[0] x counts[1] x counts[2] tiles by axis planes. Every coordinate of
/// the lattice is read from `planes` or computed by one expression from integer indices, so the tiles
/// beside a plane see it at the same double.
struct TileGrid {
  Box domain;
  std::array<int, 3> counts{1, 1, 1};
  /// Per axis, the counts[axis] + 1 plane coordinates, ascending, the first and last the domain's.
  std::array<std::vector<double>, 3> planes;

  /// The coordinate of plane `index` (0..counts[axis]) along `axis`.
  double plane(int axis, int index) const;
  /// The coordinate of sample i of m along the lattice cell `cell` of `axis` (exactly the planes at
  /// i = 0 and i = m).
  double sample(int axis, int cell, int i, int m) const;
  /// Number of tiles.
  int tile_count() const { return counts[0] * counts[1] * counts[2]; }
  /// Tile number t's lattice cell (x fastest), and back. \pre 0 <= t < tile_count().
  std::array<int, 3> tile(int t) const;
  int tile_number(const std::array<int, 3>& cell) const;
  /// The box of a tile.
  Box tile_box(const std::array<int, 3>& cell) const;
};

/// A grid of `counts` tiles of `domain`, its planes evenly spaced along each axis.
/// \throw SettingError ("tiles") when the domain is not a valid box, a count is below 1, or there are
///        more than 4096 tiles.
TileGrid make_tile_grid(const Box& domain, const std::array<int, 3>& counts);

/// make_tile_grid() with every inner plane moved (by at most a fifth of a tile, in steps of a
/// fortieth) so that f = 0 passes no corner of the lattice nearer than `clearance` (the distance
/// estimated as |f| / |grad f|) and crosses no lattice line in the plane twice within `clearance` (it
/// nearly touches that line), or keeps as far from both as those moves allow: there the curves of the
/// faces around are shorter than a base edge and the tiles' cut makes needle triangles. The same planes
/// in every process (f at the lattice alone). Costs the lattice lines' length / (clearance / 2)
/// evaluations of f per plane and try.
/// \throw as make_tile_grid(); EvaluationError where f is not finite on the lattice.
TileGrid clear_tile_grid(const Surface& surface, const Box& domain, const std::array<int, 3>& counts,
                         double clearance);

/// The counts of a grid of at least `tiles` tiles for `domain`: the count along the axis of the longest
/// tiles doubled until there are enough, so tiles stay near cubes.
/// \throw SettingError ("tiles") for tiles < 1 or > 4096.
std::array<int, 3> tile_counts(const Box& domain, int tiles);

/// How a surface is meshed in tiles: the grid (its planes cleared of the surface, clear_tile_grid()),
/// the refinement level and the target edge; the bases are made at spacing() = level * edge.
struct TilePlan {
  TileGrid grid;
  int level = 1;
  double edge = 0.0;
  /// About how many vertices the whole output has (a coarse estimate from a grid; 0 when none).
  double estimated_vertices = 0.0;
  double spacing() const { return edge * level; }
};

/// The plan of `surface` in at least `tiles` tiles (tile_counts()) of settings.box (else the surface's
/// box): the level as one process chooses it first (settings.refine, else the automatic level from a
/// coarse estimate of the curvature: the level's check on the base's own curvature is the tiles'
/// refinement guard, which halves it), the planes kept 0.4 base edges from f = 0 at the lattice's corners.
/// \throw SettingError for settings tiles do not take (the Marching Cubes method, a frame, a region or
///        cells, an error bound or a size field), for tiles narrower than 8 base edges along an axis
///        (use fewer), or as make_tile_grid(); EvaluationError.
TilePlan plan_tiles(const Surface& surface, const Settings& settings, int tiles);

/// A face of the grid: the rectangle on plane `index` of `axis` between the planes of the two other
/// axes ((axis + 1) % 3 and (axis + 2) % 3) around lattice cell `cell` of each.
struct TileFace {
  int axis = 0;
  int index = 0;
  std::array<int, 2> cell{0, 0};
  bool operator==(const TileFace&) const = default;
};

/// The six faces of a tile, in the order x lo, x hi, y lo, y hi, z lo, z hi.
std::array<TileFace, 6> tile_faces(const std::array<int, 3>& tile);

/// Every face of the grid once (faces on the domain's box included), axis by axis, then index, then
/// cells: the order face_curves() tasks are listed in.
std::vector<TileFace> grid_faces(const TileGrid& grid);

/// The curves where f = 0 meets one face of the grid, sampled for the bases beside it.
struct FaceCurves {
  TileFace face;
  double spacing = 0.0;      ///< the base edge length they were sampled at
  std::vector<Vec3> points;  ///< on the face's plane exactly and on f = 0 (to Newton's tolerance)
  /// Point numbers of each curve: an open one runs from a point on a side of the face (a crossing of a
  /// lattice edge, the same double in every face beside that edge) to another; a closed one repeats
  /// its first number at the end.
  std::vector<std::vector<std::uint32_t>> curves;
};

/// Traces the curves of f = 0 on `face` (marching squares on samples a quarter of `spacing` apart,
/// crossings by bisection on the sample edges, the curves sampled again every `spacing` of arc length
/// and put on f = 0 within the face's plane) and returns them. Depends only on the surface, the grid's
/// planes around the face and `spacing`: the crossings on a side of the face are the same in the four
/// faces that share it.
/// \throw SettingError ("spacing") for a spacing that is not positive and finite or leaves more than
///        2^24 samples on a side; EvaluationError where f is not finite.
FaceCurves face_curves(const Surface& surface, const TileGrid& grid, const TileFace& face, double spacing);

/// A tile's base: the projection mesher and the clean-up of `settings` in the tile's box at `edge` (the
/// base edge length, the curves' spacing), its cut on the tile's faces replaced by the faces' curves
/// (the band of triangles on the cut removed, the gap closed by a strip between the mesh and the
/// curves, a cap where the mesh has no part), then cleaned up again with the cut held. Every boundary
/// vertex of the result is a point of `faces`' curves, bit for bit. `faces` are the curves of the tile's
/// six faces, in tile_faces() order, each at spacing `edge`.
/// \throw InputError when `faces` are not the tile's or not at `edge`; LimitError ("tiles") when the
///        mesh cannot be joined to the curves (two curves closer than about two base edges in the tile:
///        use other tile counts or a smaller edge); the errors of mesh_surface().
Mesh tile_base(const Surface& surface, const Settings& settings, const TileGrid& grid,
               const std::array<int, 3>& tile, std::span<const FaceCurves> faces, double edge);

/// One refined tile.
struct TileMesh {
  int tile = 0;
  Mesh mesh;  ///< empty when the guard failed
  /// Per vertex of `mesh`: 1 on its cut (on a face of the tile, where the tiles are joined), else 0.
  std::vector<std::uint8_t> cut;
  std::size_t failed_points = 0;  ///< points or triangles that failed the refinement's guard
  double smallest_angle = 0.0;    ///< degrees
  /// Whether the refinement is kept: as one process keeps it (BlockMesh::kept), or with a smallest angle
  /// within half a degree of the tile base's own (a sliver of the cut, which the base has at any level).
  /// Else the caller halves the level for every tile.
  bool kept = false;
  std::size_t seam_band_vertices = 0;  ///< vertices of refined base triangles with a corner on the cut
};

/// Refines tile `tile`'s base by `level` with the preset of `settings`: every boundary edge (all on the
/// tile's faces) lands on the curve where its face's plane meets f = 0, from the edge alone, and is held,
/// so the tile across makes the same points to the bit. The landing tolerances are relative to the
/// domain's diagonal, the same in every tile. The same bytes for any thread count.
/// \throw InputError for a level outside 1..32; the errors of the refinement.
TileMesh refine_tile(const Surface& surface, const Settings& settings, const TileGrid& grid,
                     const std::array<int, 3>& tile, const Mesh& base, int level);

/// tile_base() and refine_tile() of one tile of `plan`: the job of one task. `faces` are the curves of the
/// tile's six faces at plan.spacing(), in tile_faces() order.
/// \throw as tile_base() and refine_tile().
TileMesh mesh_tile(const Surface& surface, const Settings& settings, const TilePlan& plan,
                   const std::array<int, 3>& tile, std::span<const FaceCurves> faces);

/// The whole mesh from every tile's (in any order; each tile once): tiles in ascending number, each
/// tile's vertices in order, a vertex on a tile's boundary that an earlier tile has (the same position
/// bit for bit) taken from it. The bytes do not depend on the order of `tiles`.
/// \throw InputError when a tile is missing, repeated, failed its guard, or leaves a boundary edge on an
///        inner face of the grid that no tile across has (the tiles were made from other face data);
///        LimitError when the output needs more than 2^32 - 1 vertices.
Mesh assemble_tiles(const TileGrid& grid, std::span<const TileMesh> tiles);

}  // namespace isopatch
