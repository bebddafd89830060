#pragma once
// Target edge lengths per vertex for the remesher: uniform, or from the analytic curvature for a
// chordal error bound, graded along the mesh edges.

#include <isopatch/remesh.hpp>

#include <cstdint>
#include <vector>

#include "remesh/editable_mesh.hpp"
#include "surface/sampler.hpp"

namespace isopatch {

class SizeField {
 public:
  SizeField(const Surface& surface, const RemeshSettings& settings)
      : surface_(surface), settings_(settings) {}

  /// The ungraded size at p: sizes.largest, or the varying size clamped to [sizes.smallest, sizes.largest].
  double raw(const Vec3& p);
  /// Recomputes the graded sizes of every live vertex of `mesh` (raw sizes are cached per vertex slot
  /// and computed for new slots). Afterwards at(v) is defined for every live v.
  void update(const EditableMesh& mesh);
  double at(std::uint32_t v) const { return graded_[v]; }
  /// Follows EditableMesh::compact(): `new_id[v]` is the new slot of old slot v (kDeadSlot: dropped).
  void renumber(const std::vector<std::uint32_t>& new_id);
  /// Target length of the edge a-b: the smaller of its ends' sizes.
  double edge(std::uint32_t a, std::uint32_t b) const { return std::min(graded_[a], graded_[b]); }
  std::uint64_t hessian_evaluations() const { return hessians_; }
  /// Whether sizes vary over the surface (max_error or a size callback).
  bool varies() const { return settings_.sizes.varies(); }

 private:
  const Surface& surface_;
  const RemeshSettings& settings_;
  std::vector<double> raw_;     // per vertex slot; NaN: not computed yet
  std::vector<Vec3> raw_at_;    // the position raw_ was computed at
  std::vector<double> graded_;  // per vertex slot
  std::uint64_t hessians_ = 0;
};

}  // namespace isopatch
