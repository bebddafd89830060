#pragma once
// The refinement stage of multiresolution meshing: a base mesh of f = 0 (a coarse mesh of good
// quality) cut regularly, every base triangle into k^2 triangles, the new vertices put on f = 0 and
// the lattice relaxed a little. Every vertex the refinement adds has valence 6, so the output is as
// regular as the base is, k^2 times over (the idea of semi-regular meshes, Lee et al. 2000 "Displaced
// subdivision surfaces", Guskov et al. 2000 "Normal meshes", and of Velho's 1996 "Simple and efficient
// polygonization of implicit surfaces", which subdivides a coarse polygonization and projects it).
//
// The steps, each parallel over blocks and each giving the same bytes for any thread count:
//  1. the base's edges numbered (base_edges.hpp) and the output laid out (lattice_layout.hpp): a point
//     on a base edge is made from that edge alone, so the mesh is watertight without welding;
//  2. every new point started on the Phong tessellation of the base (start_points.hpp) and put on f = 0
//     by batched Newton steps (batched_newton.hpp); a point on a boundary edge that lies on a box face or
//     region plane is put on the curve where that plane meets f = 0;
//  3. the guard: a point that lands further than half its base triangle from its start, whose normal
//     turns more than 60 degrees from the interpolated one, that does not converge, or a refined
//     triangle that turns away from the surface, fails the refinement (the caller then uses a smaller k);
//  4. Jacobi sweeps of tangential relaxation with re-projection, then sweeps aimed at the triangles
//     under an angle target and their neighbours (lattice_relaxation.hpp);
//  5. the vertices of triangles still under the floor moved one by one to raise the smallest angle
//     around them (angle_repair.hpp).
//
// A base made of pieces, each on its own function, that meet along curves known in advance (the
// patches of a composite surface: I-patches, setback vertex blends; Sipos & Salvi 2021, sec. 4) is
// refined the same way, with two differences: the points of a base edge on such a curve are the
// curve's own points (given by the caller from that edge alone, so both pieces share them), held where
// they are; every other point lands on, and relaxes on, its own piece's function.

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/stage_settings.hpp>
#include <isopatch/surface.hpp>

#include "refine/lattice_relaxation.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace isopatch::refine {

struct RefineParams {
  int level = 2;               ///< k: every base edge cut into k segments, 1..kMaxLevel
  int sweeps = 2;              ///< relaxation sweeps over the whole mesh
  int angle_sweeps = 4;        ///< sweeps over the vertices near triangles under angle_target
  double angle_target = 30.0;  ///< degrees
  /// Whether every relaxation move that leaves a triangle under angle_target with a smaller smallest
  /// angle than before is undone (lattice_relaxation.hpp, set_angle_guard).
  bool guard_angles = false;
  /// The free vertices of triangles still under this many degrees after the sweeps are moved to raise
  /// the smallest angle around them (angle_repair.hpp; 0: off). The clean-up's floor by default.
  double repair_angle = 25.0;
  std::optional<Box> box;                 ///< the box the mesh is cut by (its faces hold the cut)
  ConvexRegion region;                    ///< region planes the mesh is cut by
  std::size_t max_vertices = 0;           ///< refuse a larger output before any work (0: no limit)
  std::size_t sweep_block = kSweepBlock;  ///< vertices per block of a relaxation sweep (>= 1)
  /// The length the landing tolerances are relative to; 0: the base's bounding-box diagonal. Blocks of
  /// one base refined apart pass the whole base's, so a point they share lands the same in each.
  double scale = 0.0;
  /// Boundary edges of the base (ends a < b, base vertex numbers) that are seams with another block of
  /// a larger base: their points are landed from the edge alone and held, even on a box face or region
  /// plane, so the block across makes the same points. May be empty (no seams).
  std::function<bool(std::uint32_t a, std::uint32_t b)> seam;
  /// Whether a seam edge that lies on a box face or region plane lands on the curve where that plane
  /// meets f = 0 (still from the edge alone, and held): the seams of tiles of a box cut by planes, whose
  /// shared points must stay on the plane between them. False: a seam's points land on f = 0 only.
  bool seams_on_planes = false;
  const std::atomic<bool>* cancel = nullptr;
  std::function<void(const Progress&)> progress;  ///< may be empty
};

/// A base made of pieces on their own functions (see the file comment).
struct RefinePieces {
  std::vector<const Surface*> functions;      ///< per piece, not null; they outlive the call
  std::vector<std::uint32_t> triangle_piece;  ///< per base triangle: its piece (< functions.size())
  /// Per base vertex: the piece whose function gives its normal (a vertex on a curve lies on several),
  /// or empty: the piece of the lowest-numbered triangle that uses it. A part of a larger base refined
  /// alone passes the whole base's, so a vertex it shares starts its edges as the whole base's does.
  std::vector<std::uint32_t> vertex_piece;
  /// The points of a base edge that lies on a curve the pieces meet along (or that bounds an open
  /// piece): given the edge's ends a < b (base vertex numbers) and k, writes the k - 1 points at j/k of
  /// the way from a to b along the curve (j = 1..k-1) into `out` (size k - 1) and returns true; returns
  /// false for an edge that is not on a curve. Called once per base edge, from one thread; may be
  /// empty (no curves).
  std::function<bool(std::uint32_t a, std::uint32_t b, int k, std::span<Vec3> out)> curve_points;
};

struct RefineResult {
  Mesh mesh;  ///< empty when the guard failed (failed_points > 0)
  /// With pieces (refine_pieces): per output triangle its piece, per output vertex its piece or -1 for
  /// a vertex on a curve. Empty from refine_mesh.
  std::vector<std::uint32_t> triangle_piece;
  std::vector<std::int32_t> vertex_piece;
  std::size_t failed_points = 0;      ///< points or triangles that failed the guard (step 3)
  std::size_t rejected_moves = 0;     ///< relaxation moves undone
  std::size_t angle_vertices = 0;     ///< vertices in the aimed sweeps
  std::size_t repaired_vertices = 0;  ///< moves of the angle repair
  double smallest_angle = 0.0;        ///< over the output, degrees
  std::uint64_t gradient_evaluations = 0;
};

/// Refines `base`, a mesh of `surface` (vertices on f = 0, triangles oriented along grad f, manifold),
/// by params.level. Base vertices keep their numbers; new vertices follow (lattice_layout.hpp). The
/// attribute "role" is carried over, new vertices getting 6; other attributes are dropped.
/// \throw LimitError when the output would exceed params.max_vertices or 32-bit vertex numbers, or
///        ("cancelled") when params.cancel is set; EvaluationError when f or grad f is not finite.
RefineResult refine_mesh(const Mesh& base, const Surface& surface, const RefineParams& params);

/// Refines `base`, a mesh of the pieces of `pieces` (every triangle on its piece's function, pieces
/// meeting only along edges on which pieces.curve_points gives the points), as refine_mesh(). An edge
/// between two pieces that is not on a curve fails the guard (failed_points). Output triangle t*k^2 + i
/// belongs to base triangle t's piece. The same bytes for any thread count.
/// \throw InputError when pieces has no function, a null one, or triangle_piece or vertex_piece does not
///        match the base;
///        otherwise as refine_mesh().
RefineResult refine_pieces(const Mesh& base, const RefinePieces& pieces, const RefineParams& params);

}  // namespace isopatch::refine
