// The constrained Delaunay triangulation of a planar region (region_triangulation.hpp), on CGAL.
#include "planar/region_triangulation.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <isopatch/error.hpp>

#include <cstddef>
#include <deque>
#include <set>
#include <string>
#include <utility>

namespace isopatch::planar {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using FaceBase =
    CGAL::Triangulation_face_base_with_info_2<bool, Kernel,
                                              CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;
using Point = Kernel::Point_2;

std::string where(const Vec2& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate_region(const Region& region,
                                                             const std::vector<Vec2>& inner) {
  Cdt cdt;
  const std::size_t count = region.points.size() + inner.size();
  std::vector<Cdt::Vertex_handle> handle(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Vec2& p = i < region.points.size() ? region.points[i] : inner[i - region.points.size()];
    const std::size_t before = cdt.number_of_vertices();
    handle[i] = cdt.insert(Point(p.x(), p.y()));
    if (cdt.number_of_vertices() == before) throw CreaseError("a planar cap has two points at " + where(p));
    handle[i]->info() = static_cast<std::uint32_t>(i);
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
  try {
    for (const auto& s : region.segments) {
      cdt.insert_constraint(handle[s[0]], handle[s[1]]);
      directed.insert({s[0], s[1]});
    }
  } catch (const std::exception&) {
    throw CreaseError("the boundary curves of a planar cap cross one another near " +
                      where(region.points[region.segments.front()[0]]));
  }
  // The faces on the left of the segments, and everything reached from them without crossing one.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = false;
  std::deque<Cdt::Face_handle> queue;
  for (const auto& s : region.segments) {
    Cdt::Face_handle face;
    int i = 0;
    if (!cdt.is_edge(handle[s[0]], handle[s[1]], face, i))
      throw CreaseError("a boundary curve of a planar cap passes through one of its points near " +
                        where(region.points[s[0]]));
    if (face->vertex(Cdt::ccw(i)) != handle[s[0]]) face = face->neighbor(i);
    if (!face->info()) {
      face->info() = true;
      queue.push_back(face);
    }
  }
  while (!queue.empty()) {
    const Cdt::Face_handle face = queue.front();
    queue.pop_front();
    if (cdt.is_infinite(face))
      throw CreaseError("the boundary of a planar cap does not close (near " +
                        where(region.points[region.segments.front()[0]]) + ")");
    for (int i = 0; i < 3; ++i) {
      if (cdt.is_constrained({face, i})) {
        // A boundary edge of the region: the region must lie on its left, i.e. this face.
        const std::uint32_t a = face->vertex(Cdt::ccw(i))->info(), b = face->vertex(Cdt::cw(i))->info();
        if (!directed.count({a, b}))
          throw CreaseError(
              "the boundary curves of a planar cap do not bound one side near " +
              where(a < region.points.size() ? region.points[a] : inner[a - region.points.size()]));
        continue;
      }
      const Cdt::Face_handle across = face->neighbor(i);
      if (!across->info()) {
        across->info() = true;
        queue.push_back(across);
      }
    }
  }
  std::vector<std::array<std::uint32_t, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info()) out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return out;
}

}  // namespace isopatch::planar
