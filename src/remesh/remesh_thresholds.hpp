#pragma once
// The remesher's thresholds (remesh.cpp, docs/algorithms.md 5.3-5.8): validity of a triangle, the
// angles of the repair, the glide chains and the Laplacian-exactness sweeps, the edge-length factors
// of splits and collapses, the preview's local repair and the chordal error bound's enforcement. One
// place, so that the passes and their documentation name the same numbers.

#include <cstdint>

namespace isopatch::remesh_thresholds {

/// A triangle is valid when its normal lies within about 72 degrees of the surface normal at each of
/// its vertices: no fold, no flipped orientation, no bridge between two sheets.
constexpr double kMinNormalDot = 0.3;
/// Triangles below this smallest angle are removed by the final pass (degrees).
constexpr double kRepairAngle = 20.0;
/// The preview's local repair (run_local): triangles under this smallest angle (degrees) need it; the
/// vertices near a defect are those within kLocalRings rings of one, relaxed kLocalRelaxationRounds
/// times.
constexpr double kLocalAngle = 30.0;
constexpr int kLocalRings = 2;
constexpr int kLocalRelaxationRounds = 3;
/// Flips tried per neutral glide chain in the local repair's flip passes (200 in the whole-mesh rounds).
constexpr int kLocalGlideBudget = 30;
/// The local repair's one glide search (chains that may borrow) runs only when fewer than this share of
/// the free vertices have valence 6 once the cheaper passes are done (the last flips, relaxation and
/// repair): the search was about 40% of the preview's time. Without it the public surfaces at about 20k
/// vertices end at 91.3-96.2%; only tanglecube (91.3%) then runs it, to 93.9% (docs/algorithms.md 5.x,
/// the presets).
constexpr double kLocalValenceShare = 0.92;
/// The local repair collapses only the short edges that cells clipped near a corner leave: the patch
/// lattices' own short edges (down to about half the size across a stretched template) are kept, or
/// their collapses would leave irregular vertices behind.
constexpr double kLocalCollapseFactor = 0.35;
/// Smallest angle (degrees) a neutral flip of a glide chain may leave in its two triangles.
constexpr double kGlideAngle = 15.0;
/// The Laplacian-exactness sweeps may not take a triangle's smallest angle below min(its current one,
/// this) (degrees). 25 rather than the repair's 20: the same or lower curvature error on every surface
/// but the torus at 2k vertices (docs/whole-surface-quality.md), and a better smallest angle.
constexpr double kExactnessAngleFloor = 25.0;
/// From this many vertex slots on, every round's compaction also renumbers the vertices along the
/// space-filling curve (EditableMesh::compact_in_space_order), not only the last one: the first round's
/// splits append about as many vertices as the raw mesh has, far in memory from their neighbours, and
/// once the mesh outgrows the caches every pass then waits on memory. Side by side on the sphere, 2
/// threads: at about 1M vertices 59 s -> 36.5 s (relaxation 15.1 -> 4.3 s), at 200k (genus2) 8.1-9.3 s
/// -> 7.5-7.7 s, at 20k no change beyond the noise; below the threshold the order, and so the mesh, is
/// the one of the rounds without it (the numbering changes which of two equally good edits comes first).
constexpr std::uint32_t kSpaceOrderSlots = 50000;
/// Edge length thresholds relative to the target size. The n-gon templates stretch the patch lattice
/// (a quad patch fills 90 degrees with each 60-degree lattice wedge: 1.5 times across), so rings are
/// anisotropic (median 1.24-1.41 on the report's surfaces) until edges beyond 4/3 h are split and edges
/// under 0.7 h collapsed: median 1.17-1.19 and a lower curvature error at the same vertex count on most
/// surfaces (docs/whole-surface-quality.md; 0.8 h, Botsch & Kobbelt's 4/5, costs more on thin surfaces).
/// With a chordal error bound, edges shorter than the size are the bound's margin (size_for_error assumes
/// edges up to 4/3 h), so only slivers' edges (0.1 h) are collapsed there.
constexpr double kSplitFactor = 4.0 / 3.0;
constexpr double kCollapseFactor = 0.7;
constexpr double kErrorCollapseFactor = 0.1;
/// The chordal error bound is enforced at the end down to this fraction of EPS, in at most kBoundRounds
/// rounds of splits (enforce_error_bound).
constexpr double kBoundMargin = 0.9;
/// Within this fraction of the largest size of a region plane, a vertex lies on it (box_boundary.hpp).
constexpr double kCutPlaneTolerance = 1e-9;
constexpr int kBoundRounds = 8;

}  // namespace isopatch::remesh_thresholds
