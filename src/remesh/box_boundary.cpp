// Boundary vertices that may slide along a box face or a region's plane, see box_boundary.hpp.
#include "remesh/box_boundary.hpp"

#include <cmath>

namespace isopatch {

std::vector<int> sliding_axes(const EditableMesh& mesh, const Box& box, const std::vector<CutPlane>& planes,
                              double tolerance) {
  std::vector<int> axes(mesh.vertex_slots(), -1);
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v) {
    if (!mesh.alive(v) || !mesh.locked[v]) continue;
    int faces = 0, axis = -1;
    for (int k = 0; k < 3; ++k) {
      if (mesh.positions[v][k] == box.lo[k] || mesh.positions[v][k] == box.hi[k]) {
        ++faces;
        axis = k;
      }
    }
    if (faces != 1) continue;
    bool on_plane = false;
    for (const CutPlane& plane : planes)
      on_plane = on_plane || std::abs(plane.distance(mesh.positions[v])) <= tolerance;
    if (!on_plane) axes[v] = axis;
  }
  return axes;
}

std::vector<CutPlane> cut_planes(const ConvexRegion& region) {
  std::vector<CutPlane> planes;
  for (const HalfSpace& h : region) {
    const Vec3 n(h.a, h.b, h.c);
    const double length = n.stableNorm();
    planes.push_back({n / length, h.d / length});
  }
  return planes;
}

std::vector<int> sliding_planes(const EditableMesh& mesh, const std::vector<CutPlane>& planes, const Box* box,
                                double tolerance) {
  std::vector<int> index(mesh.vertex_slots(), -1);
  if (planes.empty()) return index;
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v) {
    if (!mesh.alive(v) || !mesh.locked[v]) continue;
    const Vec3& p = mesh.positions[v];
    if (box && ((p.array() == box->lo.array()).any() || (p.array() == box->hi.array()).any())) continue;
    int on = 0, which = -1;
    for (std::size_t k = 0; k < planes.size(); ++k)
      if (std::abs(planes[k].distance(p)) <= tolerance) {
        ++on;
        which = static_cast<int>(k);
      }
    if (on == 1) index[v] = which;
  }
  return index;
}

bool project_onto_cut_plane(const Sampler& f, Vec3& p, const std::vector<CutPlane>& planes, std::size_t k,
                            double tolerance, double margin, double max_step, Vec3* gradient) {
  const CutPlane& plane = planes[k];
  p -= plane.distance(p) * plane.normal;
  for (int it = 0; it < 30; ++it) {
    const ValueGradient vg = f.value_gradient(p);
    const Vec3 direction = vg.gradient - vg.gradient.dot(plane.normal) * plane.normal;
    const double g2 = direction.squaredNorm();
    if (!(g2 > 0.0)) return false;
    if (std::abs(vg.value) / std::sqrt(g2) <= tolerance) {
      for (std::size_t j = 0; j < planes.size(); ++j)
        if (j != k && planes[j].distance(p) >= -margin) return false;
      if (gradient) *gradient = vg.gradient;
      return true;
    }
    Vec3 step = vg.value / g2 * direction;
    if (const double length = step.norm(); length > max_step) step *= max_step / length;
    p -= step;
    p -= plane.distance(p) * plane.normal;
  }
  return false;
}

}  // namespace isopatch
