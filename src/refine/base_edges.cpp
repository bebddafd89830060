// Edges of a base mesh, numbered by their sorted end pair (base_edges.hpp).
#include "refine/base_edges.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <utility>

namespace isopatch::refine {

BaseEdges base_edges(const Mesh& base) {
  struct Side {
    std::uint32_t lo, hi, slot;  // slot = 3 * triangle + side
  };
  std::vector<Side> sides;
  sides.reserve(base.triangles.size() * 3);
  for (std::size_t t = 0; t < base.triangles.size(); ++t)
    for (std::uint32_t s = 0; s < 3; ++s) {
      const std::uint32_t a = base.triangles[t][s], b = base.triangles[t][(s + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(3 * t) + s});
    }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return std::tie(x.lo, x.hi, x.slot) < std::tie(y.lo, y.hi, y.slot);
  });
  BaseEdges edges;
  edges.of_triangle.assign(base.triangles.size(), std::array<std::uint32_t, 3>{0, 0, 0});
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    if (j - i > 255) throw InputError("the base mesh has an edge used by more than 255 triangles");
    const auto id = static_cast<std::uint32_t>(edges.ends.size());
    edges.ends.push_back({sides[i].lo, sides[i].hi});
    edges.uses.push_back(static_cast<std::uint8_t>(j - i));
    for (std::size_t m = i; m < j; ++m) edges.of_triangle[sides[m].slot / 3][sides[m].slot % 3] = id;
    i = j;
  }
  return edges;
}

}  // namespace isopatch::refine
