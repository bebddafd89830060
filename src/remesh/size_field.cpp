// Uniform and curvature-adapted sizes (see size_field.hpp and remesh.hpp).
#include "remesh/size_field.hpp"

#include "surface/target_size.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "remesh/slot_renumbering.hpp"

namespace isopatch {

double SizeField::raw(const Vec3& p) {
  if (!varies()) return settings_.sizes.largest;
  if (settings_.sizes.max_error) ++hessians_;
  return target_size(surface_, settings_.sizes, p);
}

void SizeField::update(const EditableMesh& mesh) {
  const std::size_t n = mesh.vertex_slots();
  if (!varies()) {  // one size everywhere: no per-vertex cache
    graded_.assign(n, settings_.sizes.largest);
    return;
  }
  raw_.resize(n, std::numeric_limits<double>::quiet_NaN());
  raw_at_.resize(n, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  graded_.assign(n, settings_.sizes.largest);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (!mesh.alive(v)) continue;
    if (std::isnan(raw_[v]) || raw_at_[v] != mesh.positions[v]) {
      raw_[v] = raw(mesh.positions[v]);
      raw_at_[v] = mesh.positions[v];
    }
    graded_[v] = raw_[v];
  }
  // Grading: h(v) <= h(u) + grading |u - v| along edges, by relaxation sweeps until nothing changes.
  const auto edges = mesh.edges();
  for (int sweep = 0; sweep < 64; ++sweep) {
    bool changed = false;
    for (const auto& [a, b] : edges) {
      const double length = (mesh.positions[a] - mesh.positions[b]).norm();
      const double limit_a = graded_[b] + settings_.grading * length;
      const double limit_b = graded_[a] + settings_.grading * length;
      if (graded_[a] > limit_a) graded_[a] = limit_a, changed = true;
      if (graded_[b] > limit_b) graded_[b] = limit_b, changed = true;
    }
    if (!changed) break;
  }
}

void SizeField::renumber(const std::vector<std::uint32_t>& new_id) {
  renumber_slots(raw_, new_id, std::numeric_limits<double>::quiet_NaN());
  renumber_slots(raw_at_, new_id, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()).eval());
  renumber_slots(graded_, new_id, 0.0);
}

}  // namespace isopatch
