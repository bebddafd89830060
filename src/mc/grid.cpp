// The sampling lattice of marching cubes. The outer planes are the box faces, so f is never evaluated
// outside the box; the inner planes are shifted along a direction without dyadic components, so lattice
// points avoid the symmetry planes and the rational points that catalogue surfaces tend to pass through
// exactly.
#include <isopatch/error.hpp>
#include <isopatch/marching_cubes.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace isopatch {
namespace {

/// The planes of one axis of length `cells` (in units of the cell): lo, then lo + (m - sigma) * cell for
/// every integer m with 1/2 <= m - sigma < cells - 1/2, then hi. Planes that rounding would not separate
/// from their predecessor (boxes far from the origin relative to their size) are left out, so the
/// coordinates are strictly increasing.
std::vector<double> axis_planes(double lo, double hi, double cells, double sigma, double cell) {
  std::vector<double> planes{lo};
  const double first = std::ceil(0.5 + sigma);
  const double end = std::ceil(cells - 0.5 + sigma);
  for (double m = first; m < end; m += 1.0) {
    const double x = lo + (m - sigma) * cell;
    if (x > planes.back() && x < hi) planes.push_back(x);
  }
  planes.push_back(hi);
  return planes;
}

}  // namespace

McGrid marching_cubes_grid(const Box& box, const MarchingCubesSettings& settings) {
  valid_box(box);
  settings.validate();

  McGrid grid;
  const Vec3 size = box.size();
  const double longest = size.maxCoeff();
  grid.cell = longest / settings.grid;
  const Vec3 sigma = settings.grid_offset * Vec3(0.1234, 0.5678, 0.9012);  // the shift in cells
  for (int axis = 0; axis < 3; ++axis) {
    // The side in cells, exactly settings.grid on the longest axis.
    const double cells = size[axis] == longest ? settings.grid : size[axis] / longest * settings.grid;
    grid.planes[axis] = axis_planes(box.lo[axis], box.hi[axis], cells, sigma[axis], grid.cell);
    grid.cells[axis] = static_cast<int>(grid.planes[axis].size()) - 1;
  }
  return grid;
}

}  // namespace isopatch
