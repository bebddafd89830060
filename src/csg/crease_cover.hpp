#pragma once
/// \file crease_cover.hpp
/// Where creases may be, by interval arithmetic on the expression: an octree over the box whose cells
/// are dropped when f cannot vanish in them or when every min, max and abs that reaches f takes one
/// branch throughout (one face only, expr::evaluate_interval_branches and expr::open_live_switches; each
/// cell hands its children the tape with its decided switches fixed). The cells left at the finest size are
/// the only places two faces can meet: every crease in the box passes through them, so a crease search that
/// explains every one of them has found every crease (docs/creases.md, "Every crease found"). The method is
/// the interval pruning of tape evaluators (Duff 1992, "Interval arithmetic and recursive subdivision for
/// implicit functions and constructive solid geometry"; Keeter 2020, "Massively parallel rendering of complex
/// closed-form implicit surfaces").

#include <isopatch/geometry.hpp>

#include <cstddef>
#include <utility>
#include <vector>

#include "csg/face_set.hpp"

namespace isopatch {

/// A finest cell where two faces may meet.
struct CreaseCell {
  Box box;
  /// The pairs of (merged) faces on either side of the cell's open switches, read at its centre
  /// (smaller id first, distinct faces only, sorted): the creases that may cross it.
  std::vector<std::pair<int, int>> pairs;
};

/// The cells of the cover and what the pruning did.
struct CreaseCover {
  std::vector<CreaseCell> cells;    ///< in octree order (deterministic)
  std::size_t examined = 0;         ///< cells whose interval was evaluated
  std::size_t without_surface = 0;  ///< cells dropped because f cannot vanish there
  std::size_t one_face = 0;         ///< cells dropped because one face holds there
  /// Finest cells whose open switches all join the sides of one merged face (a smooth blend): no crease.
  std::size_t smooth = 0;
  /// Cells left unexamined because the examination budget ran out (their creases are not certified).
  std::size_t over_budget = 0;
};

/// Covers `box` by an octree whose every cell halves its parent's three sides, refined where f may
/// vanish and a switch is open, down to cells whose longest side is at most `leaf`; examines at most
/// `budget` cells (cells left unexamined then count as over_budget: no crease in them is certified).
/// Deterministic: the cells come in a fixed octree order.
/// \pre leaf > 0. \throw nothing beyond what FaceSet::faces_across throws (intervals that are not
///      finite count as "may vanish", they raise no EvaluationError).
CreaseCover crease_cover(FaceSet& faces, const Box& box, double leaf, std::size_t budget);

/// The cover's default examination budget (about a second of interval evaluations on a long tape).
inline constexpr std::size_t kCoverBudget = std::size_t{1} << 20;

}  // namespace isopatch
