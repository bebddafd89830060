// The sampling lattice of marching cubes. The offset direction has no dyadic components, so lattice
// points of a shifted grid avoid the symmetry planes and the rational points that catalogue surfaces
// tend to pass through exactly.
#include <isopatch/error.hpp>
#include <isopatch/marching_cubes.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace isopatch {

McGrid marching_cubes_grid(const Box& box, const Settings& settings) {
  if (!box.valid()) throw InputError("marching cubes: the box must be finite with lo < hi on every axis");
  if (settings.grid < 1 || settings.grid > 4096)
    throw InputError("marching cubes: grid " + std::to_string(settings.grid) + " is outside 1..4096");
  if (!(settings.grid_offset >= 0.0 && settings.grid_offset < 1.0))
    throw InputError("marching cubes: grid offset must be in [0, 1)");

  const Vec3 size = box.size();
  McGrid grid;
  grid.cell = size.maxCoeff() / settings.grid;
  const Vec3 shift = settings.grid_offset * grid.cell * Vec3(0.1234, 0.5678, 0.9012);
  grid.origin = box.lo - shift;
  for (int axis = 0; axis < 3; ++axis) {
    const double cells = std::ceil((size[axis] + shift[axis]) / grid.cell - 1e-9);
    grid.cells[axis] = std::max(1, static_cast<int>(cells));
  }
  return grid;
}

}  // namespace isopatch
