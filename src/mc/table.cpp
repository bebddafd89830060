// Generates the 256-case marching cubes table at start-up from one rule instead of pasting it.
//
// Why this construction is watertight: the triangles of a case meet each cube face exactly in the
// segments computed by face_segments(), and those depend only on the four corner signs of that face.
// Ambiguous faces (negative corners on one diagonal) always cut the negative corners off separately,
// whichever cube looks at them, so two cubes sharing a face produce the same segments, traversed in
// opposite directions (the outward normals of the face are opposite). Lorensen & Cline 1987 pasted a
// table of 15 classes, whose ambiguous faces can disagree and leave holes; this rule cannot.
#include <isopatch/marching_cubes.hpp>

#include "core/cube_numbering.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <vector>

namespace isopatch {
namespace {

using cube::kCorner;
using cube::kEdge;

Vec3 corner_point(int c) {
  return Vec3(kCorner[c][0], kCorner[c][1], kCorner[c][2]);
}

Vec3 edge_midpoint(int e) {
  return 0.5 * (corner_point(kEdge[e][0]) + corner_point(kEdge[e][1]));
}

struct Segment {
  int from;  // cube edge where the segment starts
  int to;    // cube edge where it ends
};

// The segments where the surface meets face f in sign configuration `case_index`, directed so that
// each runs counter-clockwise around the patch seen from its positive side: with N the in-face
// direction from the negative to the positive side and n the outward face normal, along N x n.
std::vector<Segment> face_segments(int case_index, int f) {
  const std::array<int, 4>& corners = cube::kFace[f];
  const std::array<int, 4>& edges = cube::kFaceEdge[f];  // edges[k] joins corners[k] and corners[k + 1]

  struct Cut {
    Segment segment;
    int negative_corner;  // a corner on the negative side of the segment
  };
  std::vector<Cut> cuts;
  std::vector<int> crossed;
  for (int k = 0; k < 4; ++k)
    if (cube::crossed(case_index, edges[k])) crossed.push_back(k);
  if (crossed.size() == 2) {
    const int e = edges[crossed[0]];
    const int neg = cube::negative(case_index, kEdge[e][0]) ? kEdge[e][0] : kEdge[e][1];
    cuts.push_back({{e, edges[crossed[1]]}, neg});
  } else if (crossed.size() == 4) {
    // Ambiguous face: cut each negative corner off on its own (negative diagonal corners not joined).
    for (int k = 0; k < 4; ++k)
      if (cube::negative(case_index, corners[k]))
        cuts.push_back({{edges[(k + 3) % 4], edges[k]}, corners[k]});
  }

  Vec3 outward = Vec3::Zero();
  outward[cube::kFaceAxis[f]] = cube::face_outward_sign(f);
  std::vector<Segment> segments;
  for (const Cut& cut : cuts) {
    const Vec3 a = edge_midpoint(cut.segment.from);
    const Vec3 b = edge_midpoint(cut.segment.to);
    const Vec3 to_positive = 0.5 * (a + b) - corner_point(cut.negative_corner);
    const Vec3 along = to_positive.cross(outward);
    Segment s = cut.segment;
    if (along.dot(b - a) < 0.0) std::swap(s.from, s.to);
    segments.push_back(s);
  }
  return segments;
}

// Triangulates a loop of cube edges as a fan, which keeps the loop's orientation (counter-clockwise
// about the negative-to-positive normal). Of the loop's possible apexes, the one whose triangles
// (on edge midpoints) deviate least from the loop's mean normal is used: for the non-planar loops of
// five to seven edges a bad apex gives folded fans.
void triangulate_loop(const std::vector<int>& loop, std::vector<std::array<int, 3>>& triangles) {
  const std::size_t n = loop.size();
  auto at = [&](std::size_t apex, std::size_t i) { return loop[(apex + i) % n]; };
  auto normal = [](int a, int b, int c) {
    return Vec3((edge_midpoint(b) - edge_midpoint(a)).cross(edge_midpoint(c) - edge_midpoint(a)));
  };
  Vec3 mean = Vec3::Zero();
  for (std::size_t i = 1; i + 1 < n; ++i) mean += normal(at(0, 0), at(0, i), at(0, i + 1));
  mean.normalize();
  std::size_t best_apex = 0;
  double best_score = -2.0;
  for (std::size_t apex = 0; apex < n; ++apex) {
    double score = 1.0;
    for (std::size_t i = 1; i + 1 < n; ++i)
      score = std::min(score, normal(at(apex, 0), at(apex, i), at(apex, i + 1)).normalized().dot(mean));
    if (score > best_score + 1e-12) {
      best_score = score;
      best_apex = apex;
    }
  }
  for (std::size_t i = 1; i + 1 < n; ++i)
    triangles.push_back({at(best_apex, 0), at(best_apex, i), at(best_apex, i + 1)});
}

/// The order in which loops are started: the edges around the face z = 0, then around z = 1 (as
/// numbered), then the vertical edges by their lower corner. A loop starts at its first edge in this
/// order, which orders a case's triangles and breaks ties between equally good apexes (the planar square
/// of cases 15 and 240 is cut along the diagonal from corner 0's vertical edge).
constexpr std::array<int, 12> kLoopStartOrder = [] {
  std::array<int, 12> order{};
  int k = 0;
  for (int e = 0; e < 12; ++e)
    if (cube::edge_axis(e) != 2) order[k++] = e;
  for (int corner = 0; corner < 4; ++corner)
    for (int e = 0; e < 12; ++e)
      if (cube::edge_axis(e) == 2 && cube::edge_lower_corner(e) == corner) order[k++] = e;
  return order;
}();

McCase generate_case(int case_index) {
  // Link the directed face segments into closed loops: every crossed edge lies on two faces and is
  // the end of a segment on one of them and the start of a segment on the other.
  std::array<int, 12> next{};
  next.fill(-1);
  for (int f = 0; f < 6; ++f)
    for (const Segment& s : face_segments(case_index, f)) {
      assert(next[s.from] == -1);
      next[s.from] = s.to;
    }

  McCase result;
  std::array<bool, 12> visited{};
  for (const int start : kLoopStartOrder) {
    if (next[start] < 0 || visited[start]) continue;
    std::vector<int> loop;
    for (int e = start; !visited[e]; e = next[e]) {
      assert(next[e] >= 0);
      visited[e] = true;
      loop.push_back(e);
    }
    assert(loop.size() >= 3);
    triangulate_loop(loop, result.triangles);
  }
  return result;
}

std::array<McCase, 256> generate_table() {
  std::array<McCase, 256> table;
  for (int c = 0; c < 256; ++c) table[c] = generate_case(c);
  return table;
}

}  // namespace

const std::array<McCase, 256>& marching_cubes_table() {
  static const std::array<McCase, 256> table = generate_table();
  return table;
}

}  // namespace isopatch
