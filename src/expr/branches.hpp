#pragma once
// The switches of a tape (min, max, abs) and the smooth functions made by fixing each to one branch:
// the face functions of a CSG shape. A face of f = 0 is a connected part on which the same branches
// are active; fixing them turns f into one smooth function there (creases of CSG shapes, see
// docs/creases.md; the branch view of min/max trees follows Pasko et al. 1995, "Function
// representation in geometric modeling", and libfive's tape specialisation, Keeter 2020).

#include "expr/tape.hpp"

#include <isopatch/geometry.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace isopatch::expr {

/// A branch choice per switch of the tape (switch_instructions() order): for min and max 0 takes
/// operand a and 1 operand b; for abs 0 takes +a and 1 takes -a; kOpen leaves the switch as it is.
using BranchChoice = std::vector<std::int8_t>;
inline constexpr std::int8_t kOpen = -1;

/// The indices (into tape.code) of the min, max and abs instructions, in tape order.
std::vector<std::uint32_t> switch_instructions(const Tape& tape);

/// The branches f takes at p, with every switch whose result does not reach f through the branches
/// taken (a dead switch) set to kOpen: two points on the same smooth face give the same choice.
/// Ties (a == b, a == 0) take the branch the evaluators take (operand a; +a).
/// \pre switches == switch_instructions(tape).
BranchChoice active_branches(const Tape& tape, const std::vector<std::uint32_t>& switches, const Vec3& p);

/// One run of the tape at a point, kept per instruction: the branch each switch takes and the operands
/// it compares (the registers are reused, so they are kept as the instruction reads them).
struct SwitchValues {
  std::vector<std::int8_t> taken;  ///< kOpen for instructions that are no switch
  std::vector<std::pair<double, double>> operands;
};

/// Runs the tape at p once for the queries below.
SwitchValues switch_values(const Tape& tape, const Vec3& p);

/// The branch every switch takes where `values` were taken, live or dead.
BranchChoice all_branches(const std::vector<std::uint32_t>& switches, const SwitchValues& values);

/// `full` (a branch for every switch) with the dead switches set to kOpen: the canonical choice of the
/// face those branches make.
BranchChoice live_choice(const Tape& tape, const std::vector<std::uint32_t>& switches, BranchChoice full);

/// The first switch (index into `switches`) whose branch in `choice` f does not take where `values` were
/// taken, a tie within
/// `tolerance` counting as taken; -1 when f takes all of them there (p lies in the face's region).
int failing_switch(const Tape& tape, const std::vector<std::uint32_t>& switches, const BranchChoice& choice,
                   const SwitchValues& values, double tolerance);

/// The switches (indices into `switches`) whose branch `decided` leaves open (-1) and whose result
/// reaches f when every decided switch is fixed to its branch: where f may change from one face to
/// another. `decided` holds one entry per instruction, as evaluate_interval_branches() fills it.
/// \pre decided.size() == tape.code.size(), switches == switch_instructions(tape).
std::vector<int> open_live_switches(const Tape& tape, const std::vector<std::uint32_t>& switches,
                                    const std::vector<std::int8_t>& decided);

/// The tape with every switch whose choice is not kOpen replaced by the copy of its branch (a + 0, or
/// -a), and the instructions f no longer needs removed: a function equal to f wherever f takes those
/// branches, smooth wherever its remaining operations are.
/// \pre choice.size() == switches.size(), switches == switch_instructions(tape).
Tape specialise(const Tape& tape, const std::vector<std::uint32_t>& switches, const BranchChoice& choice);

}  // namespace isopatch::expr
