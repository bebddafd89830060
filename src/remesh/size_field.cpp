// Uniform and curvature-adapted sizes (see size_field.hpp and remesh.hpp).
#include "remesh/size_field.hpp"

#include "surface/target_size.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

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
  // Any permutation of the live slots (EditableMesh::compact keeps their order, compact_in_space_order
  // does not): gathered into new arrays.
  std::size_t size = 0;
  for (std::uint32_t v = 0; v < new_id.size(); ++v)
    if (new_id[v] != EditableMesh::kDeadSlot) size = std::max<std::size_t>(size, new_id[v] + 1);
  bool in_order = true;  // then moved down in place, with no second copy
  for (std::uint32_t v = 0, next = 0; v < new_id.size(); ++v)
    if (new_id[v] != EditableMesh::kDeadSlot) in_order = in_order && new_id[v] == next++;
  const auto squeeze = [&](auto& values, auto fill) {  // fill: a slot that had no value
    if (in_order) {
      std::size_t kept = 0;
      for (std::uint32_t v = 0; v < values.size() && v < new_id.size(); ++v)
        if (new_id[v] != EditableMesh::kDeadSlot) values[new_id[v]] = values[v], kept = new_id[v] + 1;
      values.resize(kept);
      values.resize(size, fill);
      values.shrink_to_fit();
      return;
    }
    std::remove_reference_t<decltype(values)> moved(size, fill);
    for (std::uint32_t v = 0; v < values.size() && v < new_id.size(); ++v)
      if (new_id[v] != EditableMesh::kDeadSlot) moved[new_id[v]] = values[v];
    values = std::move(moved);
  };
  squeeze(raw_, std::numeric_limits<double>::quiet_NaN());
  squeeze(raw_at_, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()).eval());
  squeeze(graded_, 0.0);
}

}  // namespace isopatch
