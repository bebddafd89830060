#pragma once
// Self-intersection check of a triangle mesh by CGAL's Polygon Mesh Processing (an independent
// implementation, used only by tests).

#include <isopatch/mesh.hpp>

#include <cstddef>

namespace isopatch::test {

/// Number of pairs of triangles that intersect other than in a shared edge or vertex (capped at
/// `limit`; 0 means the mesh does not self-intersect).
std::size_t count_self_intersections(const Mesh& mesh, std::size_t limit = 100);

}  // namespace isopatch::test
