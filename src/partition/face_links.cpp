// Polygon face linking; the orientation argument is the one of cube_cycles.hpp.
#include "partition/face_links.hpp"

#include <cstddef>

#include "core/cyclic.hpp"

namespace isopatch {

namespace {

// The side between crossed segments a and b (vertices strictly between them share one sign), directed
// a -> b when the vertex right after segment a is negative.
FaceSide side(std::span<const bool> negative, int a, int b) {
  const auto m = negative.size();
  const bool after_a = negative[next(static_cast<std::size_t>(a), m)];
  return after_a ? FaceSide{a, b} : FaceSide{b, a};
}

}  // namespace

FaceLinks link_face(std::span<const bool> negative, bool centre_negative) {
  const std::size_t m = negative.size();
  std::vector<int> crossed;
  for (std::size_t k = 0; k < m; ++k)
    if (negative[k] != negative[next(k, m)]) crossed.push_back(static_cast<int>(k));
  FaceLinks links;
  if (crossed.size() == 2) {
    links.sides.push_back(side(negative, crossed[0], crossed[1]));
  } else if (crossed.size() >= 4) {
    links.ambiguous = true;
    if (m != 4) {
      links.unresolved = true;
      return links;
    }
    // All four segments crossed. The centre joins the diagonal pair of its sign: cut off vertices 1 and
    // 3 (segments 0-1 and 2-3) when that is the pair of vertex 0, else vertices 0 and 2 (3-0, 1-2).
    if (centre_negative == negative[0]) {
      links.sides.push_back(side(negative, 0, 1));
      links.sides.push_back(side(negative, 2, 3));
    } else {
      links.sides.push_back(side(negative, 3, 0));
      links.sides.push_back(side(negative, 1, 2));
    }
  }
  return links;
}

}  // namespace isopatch
