/// \file face_set.cpp
/// Faces of a CSG shape by branch choice (face_set.hpp).
#include "csg/face_set.hpp"

#include <isopatch/error.hpp>
#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <span>
#include <string>
#include <utility>

#include "expr/branches.hpp"
#include "expr/tape.hpp"

namespace isopatch {

struct FaceSet::Tapes {
  Expression whole;
  std::vector<std::uint32_t> switches;
  std::map<std::vector<std::int8_t>, int> id_of;
};

namespace {

/// -|f - g|: zero where f equals the face function g, the first-order distance outside.
class RegionBound final : public Surface {
 public:
  RegionBound(SurfacePtr f, SurfacePtr g, const Box& box)
      : Surface("face region", box), f_(std::move(f)), g_(std::move(g)) {}
  double value(const Vec3& p) const override { return -std::abs(f_->value(p) - g_->value(p)); }
  ValueGradient value_gradient(const Vec3& p) const override {
    const ValueGradient a = f_->value_gradient(p), b = g_->value_gradient(p);
    const double d = a.value - b.value;
    if (d == 0.0) return {0.0, Vec3::UnitX()};  // inside: depth 0 / 1
    return {-std::abs(d), (d > 0.0 ? -1.0 : 1.0) * (a.gradient - b.gradient)};
  }
  SecondOrder second_order(const Vec3& p) const override {
    const ValueGradient v = value_gradient(p);
    SecondOrder s;
    s.value = v.value;
    s.gradient = v.gradient;
    return s;
  }

 private:
  SurfacePtr f_, g_;
};

class PlaneSurface final : public Surface {
 public:
  PlaneSurface(const Vec3& n, double d, const Box& box) : Surface("seam plane", box), n_(n), d_(d) {}
  double value(const Vec3& p) const override { return n_.dot(p) - d_; }
  ValueGradient value_gradient(const Vec3& p) const override { return {value(p), n_}; }
  SecondOrder second_order(const Vec3& p) const override {
    SecondOrder s;
    s.value = value(p);
    s.gradient = n_;
    return s;
  }

 private:
  Vec3 n_;
  double d_;
};

}  // namespace

FaceSet::FaceSet(const Expression& f, const Box& box)
    : tapes_(std::make_unique<Tapes>(Tapes{f, {}, {}})), box_(box) {
  tapes_->switches = expr::switch_instructions(f.tape());
  whole_ = expression_surface(f, box, "f");
}

FaceSet::~FaceSet() = default;

bool FaceSet::has_switches() const {
  return !tapes_->switches.empty();
}

int FaceSet::id_of(std::vector<std::int8_t> choice) {
  const auto [it, fresh] = tapes_->id_of.emplace(std::move(choice), static_cast<int>(choices_.size()));
  if (fresh) {
    choices_.push_back(it->first);
    parent_.push_back(it->second);
  }
  return root(it->second);
}

int FaceSet::face_at(const Vec3& p) {
  return id_of(expr::active_branches(tapes_->whole.tape(), tapes_->switches, p));
}

bool FaceSet::on_shape(const Vec3& p, const Surface& fi, double tolerance) const {
  const ValueGradient g = fi.value_gradient(p);
  return std::abs(whole_->value(p)) <= tolerance * std::max(g.gradient.norm(), 1e-300);
}

int FaceSet::boundary_face(std::span<const int> faces, const Vec3& p, double tolerance) {
  const expr::Tape& tape = tapes_->whole.tape();
  const expr::SwitchValues values = expr::switch_values(tape, p);
  for (const int face : faces) {
    // The face holds where one of its members' branches do.
    const int r = root(face);
    int failing = -1;
    std::size_t member = 0;
    bool holds = false;
    for (std::size_t m = 0; m < choices_.size() && !holds; ++m) {
      if (root(static_cast<int>(m)) != r) continue;
      const int s = expr::failing_switch(tape, tapes_->switches, choices_[m], values, tolerance);
      holds = s < 0;
      if (!holds && failing < 0) {
        failing = s;
        member = m;
      }
    }
    if (holds) continue;
    // Across: the first member's branches with the failing one switched over, the rest as f takes them.
    std::vector<std::int8_t> full = expr::all_branches(tapes_->switches, values);
    for (std::size_t k = 0; k < full.size(); ++k)
      if (choices_[member][k] != expr::kOpen) full[k] = choices_[member][k];
    full[static_cast<std::size_t>(failing)] =
        static_cast<std::int8_t>(1 - full[static_cast<std::size_t>(failing)]);
    return id_of(expr::live_choice(tape, tapes_->switches, std::move(full)));
  }
  return -1;
}

const Expression& FaceSet::expression() const {
  return tapes_->whole;
}

std::vector<std::pair<int, int>> FaceSet::faces_across(std::span<const int> switches, const Vec3& p) {
  const expr::Tape& tape = tapes_->whole.tape();
  const std::vector<std::int8_t> taken = expr::all_branches(tapes_->switches, expr::switch_values(tape, p));
  std::vector<std::pair<int, int>> out;
  out.reserve(switches.size());
  for (const int s : switches) {
    std::vector<std::int8_t> full = taken;
    std::array<int, 2> sides{};
    for (std::int8_t branch = 0; branch < 2; ++branch) {
      full[static_cast<std::size_t>(s)] = branch;
      sides[static_cast<std::size_t>(branch)] = id_of(expr::live_choice(tape, tapes_->switches, full));
    }
    out.emplace_back(sides[0], sides[1]);
  }
  return out;
}

int FaceSet::root(int face) const {
  while (parent_[static_cast<std::size_t>(face)] != face) face = parent_[static_cast<std::size_t>(face)];
  return face;
}

void FaceSet::merge(int a, int b) {
  if (!functions_.empty()) throw Error(ErrorKind::Internal, "faces merged after their functions were made");
  a = root(a);
  b = root(b);
  if (a == b) return;
  parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
}

const SurfacePtr& FaceSet::function(int face) {
  face = root(face);
  if (functions_.size() < choices_.size()) {
    functions_.resize(choices_.size());
    bounds_.resize(choices_.size());
  }
  SurfacePtr& out = functions_[static_cast<std::size_t>(face)];
  if (!out) {
    // The branch of each switch that the members where it is live agree on; a switch they take
    // different branches of stays open (a switch dead in a member does not matter to it).
    std::vector<std::int8_t> shared(choices_[static_cast<std::size_t>(face)].size(), expr::kOpen);
    std::vector<bool> conflict(shared.size(), false);
    for (std::size_t m = 0; m < choices_.size(); ++m)
      if (root(static_cast<int>(m)) == face)
        for (std::size_t s = 0; s < shared.size(); ++s) {
          const std::int8_t c = choices_[m][s];
          if (c == expr::kOpen) continue;
          if (shared[s] == expr::kOpen && !conflict[s])
            shared[s] = c;
          else if (shared[s] != c) {
            conflict[s] = true;
            shared[s] = expr::kOpen;
          }
        }
    auto tape =
        std::make_shared<const expr::Tape>(expr::specialise(tapes_->whole.tape(), tapes_->switches, shared));
    out = expression_surface(Expression(std::move(tape)), box_, "face " + std::to_string(face));
  }
  return out;
}

const SurfacePtr& FaceSet::fine_function(int face) {
  if (fine_.size() < choices_.size()) fine_.resize(choices_.size());
  SurfacePtr& out = fine_[static_cast<std::size_t>(face)];
  if (!out) {
    auto tape = std::make_shared<const expr::Tape>(
        expr::specialise(tapes_->whole.tape(), tapes_->switches, choices_[static_cast<std::size_t>(face)]));
    out = expression_surface(Expression(std::move(tape)), box_, "branch " + std::to_string(face));
  }
  return out;
}

SurfacePtr FaceSet::region_bound(int face) {
  face = root(face);
  const SurfacePtr& g = function(face);
  SurfacePtr& out = bounds_[static_cast<std::size_t>(face)];
  if (!out) out = std::make_shared<RegionBound>(whole_, g, box_);
  return out;
}

SurfacePtr plane_surface(const Vec3& normal, double offset, const Box& box) {
  return std::make_shared<PlaneSurface>(normal, offset, box);
}

}  // namespace isopatch
