// Boundary vertices that may slide along a box face, see box_boundary.hpp.
#include "remesh/box_boundary.hpp"

namespace isopatch {

std::vector<int> sliding_axes(const EditableMesh& mesh, const Box& box) {
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
    if (faces == 1) axes[v] = axis;
  }
  return axes;
}

}  // namespace isopatch
