#pragma once
/// \file face_parts.hpp
/// The parts of a CSG shape's faces on the coarse mesh of the crease search (its vertices joined by its
/// edges, face by face, split by the planes that cut them) and the shape of a face's boundary cycle:
/// what face_regions.cpp decides its cuts from. docs/creases.md.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <vector>

#include "csg/crease_graph.hpp"
#include "csg/crease_search.hpp"
#include "csg/face_cycles.hpp"

namespace isopatch {

/// The parts of the faces on the coarse mesh.
struct Parts {
  std::vector<int> part;                     // per vertex
  std::vector<std::vector<int>> neighbours;  // per vertex
  int count = 0;

  /// Components of the vertices of `members` joined by edges that `keep` accepts, numbered from `first`
  /// (the first component keeps `first`, the others get new numbers).
  template <class Keep>
  void relabel(const std::vector<int>& members, int first, Keep keep) {
    std::vector<int> stack;
    const int old = part[static_cast<std::size_t>(members.front())];
    for (const int v : members) part[static_cast<std::size_t>(v)] = -2 - old;  // unvisited marker
    bool first_used = false;
    for (const int s : members) {
      if (part[static_cast<std::size_t>(s)] != -2 - old) continue;
      const int id = first_used ? count++ : first;
      first_used = true;
      part[static_cast<std::size_t>(s)] = id;
      stack.push_back(s);
      while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        for (const int w : neighbours[static_cast<std::size_t>(v)])
          if (part[static_cast<std::size_t>(w)] == -2 - old && keep(v, w)) {
            part[static_cast<std::size_t>(w)] = id;
            stack.push_back(w);
          }
      }
    }
  }
};

/// Every vertex of the coarse mesh in the part of its face it is joined to by edges.
Parts initial_parts(const ShapeSamples& s);

/// The plane of a cut.
struct Plane {
  Vec3 normal = Vec3::UnitX();
  double offset = 0.0;
  double at(const Vec3& p) const { return normal.dot(p) - offset; }
};

/// The points of a cycle and its best-fit plane normal.
struct CycleShape {
  std::vector<Vec3> points;
  Vec3 centroid = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double length = 0.0;
};

/// The points of a cycle (each node once), their centroid, best-fit plane normal and length.
CycleShape cycle_shape(const CreaseGraph& g, const FaceCycle& c);

/// The most concave stretch of a cycle: where, walking it with the piece on the left, the boundary
/// turns right (about the face's normal) the most in a row, straight stretches included.
struct Concavity {
  double turn = 0.0;           ///< the stretch's total right turn (radians, >= 0)
  Vec3 middle = Vec3::Zero();  ///< where half of it is turned
  Vec3 chord = Vec3::UnitX();  ///< from its first to its last turning point
  double sharpest = 0.0;       ///< the largest right turn at one point (a reflex corner)
  Vec3 sharpest_at = Vec3::Zero();
  Vec3 sharpest_in = Vec3::UnitX();  ///< the direction the boundary arrives at it
};

/// The most concave stretch of the cycle of shape `s` on face function `f`.
Concavity concavity(const CycleShape& s, const Surface& f);

}  // namespace isopatch
