#pragma once
/// \file to_mesh.hpp
/// A CGAL::Surface_mesh of triangles as an isopatch Mesh (the CGAL peers' output step).

#include <isopatch/mesh.hpp>

#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace isopatch::bench {

/// The vertices of `cgal` in its order and its triangular faces (other faces are skipped), with the
/// orientation of its halfedges. \pre no removed elements (collect_garbage() first)
template <class CgalMesh>
Mesh to_mesh(const CgalMesh& cgal) {
  Mesh mesh;
  mesh.positions.reserve(cgal.number_of_vertices());
  std::vector<std::uint32_t> index(cgal.num_vertices());
  for (const auto v : cgal.vertices()) {
    const auto& p = cgal.point(v);
    index[v.idx()] = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(p.x(), p.y(), p.z());
  }
  mesh.triangles.reserve(cgal.number_of_faces());
  for (const auto f : cgal.faces()) {
    Triangle t{};
    std::size_t i = 0;
    for (const auto v : CGAL::vertices_around_face(cgal.halfedge(f), cgal)) {
      if (i < 3) t[i] = index[v.idx()];
      ++i;
    }
    if (i == 3) mesh.triangles.push_back(t);
  }
  return mesh;
}

}  // namespace isopatch::bench
