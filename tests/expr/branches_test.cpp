// Switches of a tape and the face functions made by fixing them (expr/branches.hpp).
#include <gtest/gtest.h>

#include <isopatch/expression.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "expr/branches.hpp"
#include "expr/evaluate.hpp"
#include "expr/tape.hpp"

namespace isopatch::expr {
namespace {

constexpr const char* kCubeFormula = "max(max(abs(x),abs(y)),abs(z))-1";

TEST(Branches, ACubeHasFiveSwitchesAndSixFaces) {
  const Expression f = parse_expression(kCubeFormula);
  const auto switches = switch_instructions(f.tape());
  EXPECT_EQ(switches.size(), 5u);  // three abs, two max
  // The six face centres give six different choices; a point and its neighbour on the same face agree.
  const Vec3 centres[] = {{1, 0.1, 0.2},  {-1, 0.1, 0.2}, {0.1, 1, 0.2},
                          {0.1, -1, 0.2}, {0.1, 0.2, 1},  {0.1, 0.2, -1}};
  std::vector<BranchChoice> seen;
  for (const Vec3& p : centres) {
    const BranchChoice c = active_branches(f.tape(), switches, p);
    // Another point of the same face (its two small coordinates changed).
    Vec3 q = p;
    for (int a = 0; a < 3; ++a)
      if (std::abs(p[a]) < 0.5) q[a] = -0.6 * p[a] + 0.3;
    EXPECT_EQ(c, active_branches(f.tape(), switches, q));
    for (const BranchChoice& other : seen) EXPECT_NE(c, other);
    seen.push_back(c);
  }
}

TEST(Branches, DeadSwitchesAreOpen) {
  const Expression f = parse_expression(kCubeFormula);
  const auto switches = switch_instructions(f.tape());
  // On the face x = 1 the abs of y and z do not reach f: they are open.
  const BranchChoice c = active_branches(f.tape(), switches, {1.0, 0.2, 0.3});
  int open = 0;
  for (const auto s : c) open += s == kOpen ? 1 : 0;
  EXPECT_EQ(open, 2);
}

TEST(Branches, AFaceFunctionIsSmoothAndEqualsFWhereItsBranchesHold) {
  const Expression f = parse_expression(kCubeFormula);
  const auto switches = switch_instructions(f.tape());
  const BranchChoice c = active_branches(f.tape(), switches, {1.0, 0.2, 0.3});
  const Expression face(std::make_shared<const Tape>(specialise(f.tape(), switches, c)));
  // The face function is the plane x - 1 everywhere, fewer instructions than f.
  for (const Vec3& p : {Vec3(0.3, -2.0, 5.0), Vec3(-4.0, 0.0, 0.1), Vec3(1.0, 0.2, 0.3)}) {
    EXPECT_DOUBLE_EQ(face.value(p), p.x() - 1.0);
    EXPECT_DOUBLE_EQ(face.value_gradient(p).gradient.x(), 1.0);
  }
  EXPECT_LT(face.tape().code.size(), f.tape().code.size());
  // Where the branches hold it equals f; failing_switch says where they do not.
  EXPECT_EQ(failing_switch(f.tape(), switches, c, switch_values(f.tape(), {1.0, 0.2, 0.3}), 1e-12), -1);
  EXPECT_EQ(face.value({1.2, 0.5, -0.4}), f.value({1.2, 0.5, -0.4}));
  EXPECT_GE(failing_switch(f.tape(), switches, c, switch_values(f.tape(), {0.2, 1.0, 0.3}), 1e-12), 0);
  // A tie within the tolerance counts as taken (a point on a crease).
  EXPECT_EQ(failing_switch(f.tape(), switches, c, switch_values(f.tape(), {1.0, 1.0 + 1e-13, 0.3}), 1e-9),
            -1);
}

TEST(Branches, AbsOfOneSignIsOneFunction) {
  // abs(x^2+y^2+z^2-1)-0.1: the shell's two sheets are different faces (+g and -g).
  const Expression f = parse_expression("abs(x^2+y^2+z^2-1)-0.1");
  const auto switches = switch_instructions(f.tape());
  ASSERT_EQ(switches.size(), 1u);
  EXPECT_NE(active_branches(f.tape(), switches, {1.05, 0, 0}),
            active_branches(f.tape(), switches, {0.95, 0, 0}));
  EXPECT_EQ(active_branches(f.tape(), switches, {1.05, 0, 0}),
            active_branches(f.tape(), switches, {0, 0, -1.05}));
}

TEST(Branches, ATapeWithoutSwitchesHasNone) {
  const Expression f = parse_expression("x^2+y^2+z^2-1");
  EXPECT_TRUE(switch_instructions(f.tape()).empty());
  EXPECT_TRUE(active_branches(f.tape(), {}, {1, 0, 0}).empty());
}

TEST(Branches, IntervalsDecideASwitchOnlyWhereOneBranchHoldsThroughoutTheBox) {
  const Expression f = parse_expression("max(min(x,2),abs(y-1))");
  const Tape& tape = f.tape();
  const auto switches = switch_instructions(tape);
  ASSERT_EQ(switches.size(), 3u);  // min, abs, max in tape order
  const auto decided_at = [&](const Box& box) {
    std::vector<std::int8_t> decided;
    const Interval range = evaluate_interval_branches(tape, box, decided);
    EXPECT_EQ(decided.size(), tape.code.size());
    EXPECT_TRUE(range.contains(evaluate(tape, box.centre())));
    std::vector<std::int8_t> out;
    for (const std::uint32_t s : switches) out.push_back(decided[s]);
    return out;
  };
  const auto which = [&](Op op) {
    for (std::size_t s = 0; s < switches.size(); ++s)
      if (tape.code[switches[s]].op == op) return s;
    return switches.size();
  };
  const std::size_t min_s = which(Op::Min), abs_s = which(Op::Abs), max_s = which(Op::Max);
  // x in [0, 1]: min takes x; y - 1 in [2, 3]: abs takes +; max(x, |y - 1|) takes the abs.
  std::vector<std::int8_t> d = decided_at({Vec3(0, 3, 0), Vec3(1, 4, 1)});
  EXPECT_EQ(d[min_s], 0);
  EXPECT_EQ(d[abs_s], 0);
  EXPECT_EQ(d[max_s], 1);
  // x in [3, 4]: min takes 2; y - 1 in [-3, -2]: abs negates.
  d = decided_at({Vec3(3, -2, 0), Vec3(4, -1, 1)});
  EXPECT_EQ(d[min_s], 1);
  EXPECT_EQ(d[abs_s], 1);
  // Boxes across a switch leave it open; the tie x = 2 on the box's edge takes operand a, as the point
  // evaluators do.
  d = decided_at({Vec3(1.5, 0.5, 0), Vec3(2.5, 1.5, 1)});
  EXPECT_EQ(d[min_s], kOpen);
  EXPECT_EQ(d[abs_s], kOpen);
  EXPECT_EQ(decided_at({Vec3(1, 3, 0), Vec3(2, 4, 1)})[min_s], 0);
}

TEST(Branches, OnlyOpenSwitchesThatReachTheResultAreListed) {
  // On the cube's face x = 1, away from its edges: the outer switches pick |x|, so the abs of y and z
  // and the max between them are dead; only cells across the face's edges leave a live switch open.
  const Expression f = parse_expression(kCubeFormula);
  const Tape& tape = f.tape();
  const auto switches = switch_instructions(tape);
  std::vector<std::int8_t> decided;
  evaluate_interval_branches(tape, {Vec3(0.9, -0.1, 0.2), Vec3(1.1, 0.1, 0.4)}, decided);
  EXPECT_TRUE(open_live_switches(tape, switches, decided).empty());
  // Across the edge x = y = 1: the max of |x| and |y| is open and live.
  evaluate_interval_branches(tape, {Vec3(0.9, 0.9, 0.2), Vec3(1.1, 1.1, 0.4)}, decided);
  const std::vector<int> open = open_live_switches(tape, switches, decided);
  ASSERT_EQ(open.size(), 1u);
  EXPECT_EQ(tape.code[switches[static_cast<std::size_t>(open[0])]].op, Op::Max);
  // On the face z = 1 across the plane x = 0: |x| is open but dead (the outer max takes |z| there).
  evaluate_interval_branches(tape, {Vec3(-0.1, 0.2, 0.9), Vec3(0.1, 0.3, 1.1)}, decided);
  EXPECT_TRUE(open_live_switches(tape, switches, decided).empty());
}

TEST(Branches, ATapeSpecialisedOverABoxGivesTheSameIntervalsInsideIt) {
  // Fixing the switches decided over a parent box must not widen its children's intervals: a tie such
  // as |y| >= |z| touching exactly on a child's side stays decided (the copies are exact).
  const Expression f = parse_expression(kCubeFormula);
  const Tape& tape = f.tape();
  const auto switches = switch_instructions(tape);
  const Box parent{Vec3(-0.84375, -1.03125, -0.984375), Vec3(-0.75, -0.9375, -0.890625)};
  std::vector<std::int8_t> decided;
  evaluate_interval_branches(tape, parent, decided);
  BranchChoice choice(switches.size(), kOpen);
  for (std::size_t s = 0; s < switches.size(); ++s) choice[s] = decided[switches[s]];
  const Tape pruned = specialise(tape, switches, choice);
  EXPECT_LT(pruned.code.size(), tape.code.size());
  const Box child{Vec3(-0.84375, -1.03125, -0.984375), Vec3(-0.796875, -0.984375, -0.9375)};
  std::vector<std::int8_t> full_decided, pruned_decided;
  const Interval a = evaluate_interval_branches(tape, child, full_decided);
  const Interval b = evaluate_interval_branches(pruned, child, pruned_decided);
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
  EXPECT_EQ(open_live_switches(tape, switches, full_decided).size(),
            open_live_switches(pruned, switch_instructions(pruned), pruned_decided).size());
}

}  // namespace
}  // namespace isopatch::expr
