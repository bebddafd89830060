// Face-by-face linking of crossed cube edges; see cube_cycles.hpp for the orientation argument.
#include "partition/cube_cycles.hpp"

#include "core/cube_numbering.hpp"

#include <array>
#include <cassert>

namespace isopatch {

namespace {

bool corner_bit(std::uint8_t negative, int corner) {
  return ((negative >> corner) & 1u) != 0;
}

struct Link {
  int next = -1;  // the edge this edge's crossing is linked to, along the orientation
  int face = -1;  // the face holding that side
};

// Records the directed side a -> b on `face`, where the face corners strictly between edge a and edge b
// (counter-clockwise from outside) are `first`, ... In the caller `first` is the corner right after
// edge a: when it is negative the side goes a -> b (negative corners on the right), else b -> a.
void add_side(std::array<Link, 12>& links, int face, int a, int b, bool first_negative) {
  const int from = first_negative ? a : b;
  const int to = first_negative ? b : a;
  assert(links[from].next == -1);
  links[from] = Link{to, face};
}

}  // namespace

bool face_ambiguous(std::uint8_t negative, int face) {
  const auto& c = cube::kFace[face];
  const bool n0 = corner_bit(negative, c[0]);
  const bool n1 = corner_bit(negative, c[1]);
  return n0 == corner_bit(negative, c[2]) && n1 == corner_bit(negative, c[3]) && n0 != n1;
}

std::uint16_t crossed_edges(std::uint8_t negative) {
  std::uint16_t mask = 0;
  for (int e = 0; e < 12; ++e)
    if (corner_bit(negative, cube::kEdge[e][0]) != corner_bit(negative, cube::kEdge[e][1]))
      mask = static_cast<std::uint16_t>(mask | (1u << e));
  return mask;
}

std::vector<CubeCycle> cube_cycles(std::uint8_t negative, std::uint8_t centre_negative) {
  std::array<Link, 12> links{};
  for (int f = 0; f < 6; ++f) {
    const auto& corner = cube::kFace[f];
    const auto& edge = cube::kFaceEdge[f];
    // Edge k of the face runs from corner k to corner k + 1; corner k + 1 comes right after it.
    auto after = [&](int k) { return corner_bit(negative, corner[(k + 1) % 4]); };
    if (face_ambiguous(negative, f)) {
      const bool centre_like_0 = corner_bit(centre_negative, f) == corner_bit(negative, corner[0]);
      // Joined with corners 0 and 2: cut off corners 1 and 3 (sides 0-1 and 2-3); else cut off 0 and 2.
      const int k0 = centre_like_0 ? 0 : 3;
      for (int k : {k0, (k0 + 2) % 4}) add_side(links, f, edge[k], edge[(k + 1) % 4], after(k));
      continue;
    }
    std::array<int, 2> crossed{};
    int count = 0;
    for (int k = 0; k < 4; ++k)
      if (corner_bit(negative, corner[k]) != after(k)) crossed[static_cast<std::size_t>(count++)] = k;
    if (count == 0) continue;
    assert(count == 2);
    // Corners after edge crossed[0] up to edge crossed[1] all share the sign of the first of them.
    add_side(links, f, edge[crossed[0]], edge[crossed[1]], after(crossed[0]));
  }

  std::vector<CubeCycle> cycles;
  const std::uint16_t crossed = crossed_edges(negative);
  std::array<bool, 12> visited{};
  for (int start = 0; start < 12; ++start) {
    if (!((crossed >> start) & 1u) || visited[start]) continue;
    CubeCycle cycle;
    for (int e = start; !visited[e]; e = links[e].next) {
      assert(links[e].next >= 0);
      visited[e] = true;
      cycle.edges.push_back(e);
      cycle.faces.push_back(links[e].face);
    }
    cycles.push_back(std::move(cycle));
  }
  return cycles;
}

}  // namespace isopatch
