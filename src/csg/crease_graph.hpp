#pragma once
/// \file crease_graph.hpp
/// The curves a CSG shape is meshed along: its creases (where two faces meet) and the seams that cut
/// faces into disc-like pieces, each a dense polyline exactly on its two functions, joined at nodes
/// (corners where three faces meet, points where a seam meets a crease, split points). docs/creases.md.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace isopatch {

/// A point where curves meet.
struct GraphNode {
  Vec3 position = Vec3::Zero();
};

/// One curve: from node `start` to node `end` (equal for a closed loop with one node), with face
/// `left` on its left and face `right` on its right seen from outside the solid (the same face for a
/// seam). Its points are on `first` = `second` = 0.
struct GraphCurve {
  std::vector<Vec3> points;  ///< dense, start to end; a closed loop repeats its first point last
  int start = -1;
  int end = -1;
  int left = -1;
  int right = -1;
  SurfacePtr first;
  SurfacePtr second;
  bool seam = false;
  /// A seam's plane: plane_normal . x = plane_offset (`second` is that plane).
  Vec3 plane_normal = Vec3::Zero();
  double plane_offset = 0.0;
};

/// "(x, y, z)" with 6 significant digits, for errors and warnings.
inline std::string point_text(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return buf;
}

/// The nodes and curves of a shape.
struct CreaseGraph {
  std::vector<GraphNode> nodes;
  std::vector<GraphCurve> curves;

  /// The node at p: an existing one within `tolerance`, else a new one.
  int node_at(const Vec3& p, double tolerance) {
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if ((nodes[i].position - p).norm() <= tolerance) return static_cast<int>(i);
    nodes.push_back({p});
    return static_cast<int>(nodes.size() - 1);
  }
};

}  // namespace isopatch
