// Switches of a tape and the face functions made by fixing them (expr/branches.hpp).
#include <gtest/gtest.h>

#include <isopatch/expression.hpp>

#include <cmath>
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

}  // namespace
}  // namespace isopatch::expr
