/// \file crease_cover.cpp
/// The interval cover of the places two faces may meet (crease_cover.hpp). Each cell passes its
/// children the tape with the switches it decided fixed and what no longer reaches f dropped
/// (expr::specialise): equal to f throughout the cell, shorter, and with tighter intervals.
#include "csg/crease_cover.hpp"

#include <isopatch/expression.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>

#include "expr/branches.hpp"
#include "expr/evaluate.hpp"
#include "expr/tape.hpp"

namespace isopatch {

namespace {

/// f as a cell's ancestors left it: a tape equal to f in the cell, its switches, and which switch of
/// the whole tape each one is.
struct PrunedTape {
  expr::Tape tape;
  std::vector<std::uint32_t> switches;
  std::vector<int> original;
};

/// The eight children of a cell, each axis halved, in a fixed order.
std::array<Box, 8> octants(const Box& box) {
  const Vec3 mid = box.centre();
  std::array<Box, 8> out;
  for (std::size_t k = 0; k < 8; ++k)
    for (int a = 0; a < 3; ++a) {
      const bool upper = ((k >> a) & 1U) != 0U;
      out[k].lo[a] = upper ? mid[a] : box.lo[a];
      out[k].hi[a] = upper ? box.hi[a] : mid[a];
    }
  return out;
}

/// The tape with the switches `decided` fixed, keeping `open` (indices into from.switches, the
/// switches left open and live, in tape order: exactly those specialise() keeps).
std::shared_ptr<const PrunedTape> prune(const PrunedTape& from, const std::vector<std::int8_t>& decided,
                                        const std::vector<int>& open) {
  auto out = std::make_shared<PrunedTape>();
  expr::BranchChoice choice(from.switches.size(), expr::kOpen);
  for (std::size_t s = 0; s < from.switches.size(); ++s) choice[s] = decided[from.switches[s]];
  out->tape = expr::specialise(from.tape, from.switches, choice);
  out->switches = expr::switch_instructions(out->tape);
  for (const int s : open) out->original.push_back(from.original[static_cast<std::size_t>(s)]);
  return out;
}

}  // namespace

CreaseCover crease_cover(FaceSet& faces, const Box& box, double leaf, std::size_t budget) {
  CreaseCover out;
  auto whole = std::make_shared<PrunedTape>();
  whole->tape = faces.expression().tape();
  whole->switches = expr::switch_instructions(whole->tape);
  for (std::size_t s = 0; s < whole->switches.size(); ++s) whole->original.push_back(static_cast<int>(s));
  std::vector<std::pair<Box, std::shared_ptr<const PrunedTape>>> stack{{box, whole}};
  std::vector<std::int8_t> decided;
  while (!stack.empty()) {
    const auto [cell, f] = stack.back();
    stack.pop_back();
    if (out.examined == budget) {
      ++out.over_budget;
      continue;
    }
    ++out.examined;
    const Interval range = expr::evaluate_interval_branches(f->tape, cell, decided);
    if (range.excludes_zero()) {
      ++out.without_surface;
      continue;
    }
    const std::vector<int> open = expr::open_live_switches(f->tape, f->switches, decided);
    if (open.empty()) {
      ++out.one_face;
      continue;
    }
    if (cell.size().maxCoeff() > leaf) {
      const std::shared_ptr<const PrunedTape> next =
          open.size() < f->switches.size() ? prune(*f, decided, open) : f;
      const std::array<Box, 8> children = octants(cell);
      for (auto c = children.rbegin(); c != children.rend(); ++c) stack.emplace_back(*c, next);
      continue;
    }
    CreaseCell c;
    c.box = cell;
    std::vector<int> switches;
    switches.reserve(open.size());
    for (const int s : open) switches.push_back(f->original[static_cast<std::size_t>(s)]);
    for (const auto& [a, b] : faces.faces_across(switches, cell.centre()))
      if (a != b) c.pairs.emplace_back(std::min(a, b), std::max(a, b));
    std::sort(c.pairs.begin(), c.pairs.end());
    c.pairs.erase(std::unique(c.pairs.begin(), c.pairs.end()), c.pairs.end());
    if (c.pairs.empty()) {
      ++out.smooth;
      continue;
    }
    out.cells.push_back(std::move(c));
  }
  return out;
}

}  // namespace isopatch
