#pragma once
/// \file lattice.hpp
/// The integer lattice under the octree (docs/algorithms.md 2.1) and the keys that name its points, segments
/// and faces. Every position the partition uses is computed from integer coordinates by one function,
/// so cells sharing a point see bit-identical coordinates and values.

#include <isopatch/geometry.hpp>

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace isopatch {

/// Integer coordinates on a lattice (the finest lattice, or the half lattice, see Lattice).
using LatticePoint = std::array<std::uint32_t, 3>;

/// The cubic root cell and its lattice at the finest depth D = max_depth: the point with finest
/// coordinates (i, j, k) is origin + (i, j, k) * size / 2^D. The half lattice (step size / 2^(D+1))
/// also holds the centres of faces and cells at depth D.
struct Lattice {
  Vec3 origin = Vec3::Zero();
  double size = 1.0;  ///< side of the root cube
  int max_depth = 0;  ///< D, 0..kMaxDepth
  /// The user's box: every position is clamped into it, so f is never evaluated outside it. Cells that
  /// straddle the box become the part inside; cells outside it are flat (see Lattice::inside).
  Box clip{Vec3::Constant(-std::numeric_limits<double>::infinity()),
           Vec3::Constant(std::numeric_limits<double>::infinity())};

  static constexpr int kMaxDepth = 20;

  /// The finest lattice step, size / 2^D.
  double unit() const;
  /// The side of a cell at `depth`, in finest lattice steps: 2^(D - depth).
  std::uint32_t step(int depth) const { return 1u << (max_depth - depth); }
  /// The point with half-lattice coordinates h (in units of unit() / 2).
  Vec3 half_point(const LatticePoint& h) const;
  /// The point with finest coordinates p; bit-identical to half_point(2p).
  Vec3 point(const LatticePoint& p) const;
  /// The box of the cell with coordinates `cell` at `depth` (cell sizes from the root's lower corner),
  /// clamped to `clip`.
  Box cell_box(int depth, const LatticePoint& cell) const;
  /// Whether the cell has a part of positive volume inside `clip` (cells outside are skipped).
  bool inside(int depth, const LatticePoint& cell) const;
};

/// The root cube of docs/algorithms.md 2.1: `box` made cubic (its longest side), grown by 2% and shifted by
/// the non-dyadic offset 1e-3 * size * (0.1234, 0.5678, 0.9012), so symmetric surfaces do not pass
/// through lattice points. The result still contains `box`, and clips its positions to `box`.
/// \throw InputError if !box.valid() or max_depth is outside 0..Lattice::kMaxDepth.
Lattice make_lattice(const Box& box, int max_depth);

/// A packed 64-bit key of a half-lattice point (coordinates <= 2^21), injective: mixed radix 2^21 + 1.
std::uint64_t half_key(const LatticePoint& h);

/// A lattice segment: `length` finest steps along `axis` from `start` (finest coordinates). A cell
/// edge at depth L is the segment of length 2^(D - L) from its lower end.
struct SegmentKey {
  LatticePoint start{};
  std::uint32_t axis = 0;
  std::uint32_t length = 0;

  friend auto operator<=>(const SegmentKey&, const SegmentKey&) = default;
  LatticePoint end() const;
};

/// A square lattice face: normal `axis`, lower corner `lower` (finest coordinates; lower[axis] is the
/// plane's coordinate) and side `size` in finest steps. Two cells sharing the face compute the same id.
struct FaceId {
  LatticePoint lower{};
  std::uint32_t axis = 0;
  std::uint32_t size = 0;

  std::uint32_t plane() const { return lower[axis]; }
  friend auto operator<=>(const FaceId&, const FaceId&) = default;
};

/// The finest-lattice points whose finest cells have the segment's start on an edge parallel to the
/// segment: start, start - e_u, start - e_v and start - e_u - e_v (u, v the other two axes), those
/// without a negative coordinate. A cell at a coarser depth around the segment contains one of them.
struct CellsAroundSegment {
  std::array<LatticePoint, 4> points{};
  std::size_t count = 0;
};
CellsAroundSegment cells_around_segment(const SegmentKey& key);

struct SegmentKeyHash {
  std::size_t operator()(const SegmentKey& key) const;
};

struct FaceIdHash {
  std::size_t operator()(const FaceId& id) const;
};

}  // namespace isopatch
