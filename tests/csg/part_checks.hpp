#pragma once
// The checks of a lattice part meshed along its creases (capped by planes or cut by a curved solid):
// closed, manifold, outward, free of self-intersections, every vertex on f = 0, every crease vertex on
// both of its faces, the valence and angle floors.
#include <gtest/gtest.h>

#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "mesh_checks.hpp"
#include "self_intersection.hpp"

namespace isopatch::test {

struct CappedRun {
  SurfacePtr surface;
  Mesh mesh;
  MeshStats stats;
};

/// The cube [-a, a]^3.
inline Box cube_box(double a) {
  return {Vec3::Constant(-a), Vec3::Constant(a)};
}

/// `formula` meshed in cube_box(a) at edge length `edge` (`threads` 0: the default), with its statistics.
inline CappedRun mesh_in_cube(const std::string& formula, double a, double edge, int threads = 0) {
  CappedRun run;
  run.surface = expression_surface(formula, cube_box(a));
  Settings s;
  s.box = cube_box(a);
  s.edge_length = edge;
  s.threads = threads;
  run.mesh = mesh_surface(*run.surface, s, &run.stats);
  return run;
}

/// The formulas as surfaces over cube_box(a) (a part's face functions).
inline std::vector<SurfacePtr> surfaces_in_cube(const std::vector<std::string>& formulas, double a) {
  std::vector<SurfacePtr> out;
  for (const std::string& f : formulas) out.push_back(expression_surface(f, cube_box(a)));
  return out;
}

/// Checks a capped part: closed, manifold, outward, no self-intersection, vertices on f = 0, every
/// vertex where a cap triangle meets a triangle off that cap on both faces, the angle and valence floors;
/// `planar_caps`: the statistics count planar caps (a curved cut has none). Triangles whose centroid
/// `exempt` accepts (when given: a known limit, such as a box corner inside a sheet) skip the angle floor.
inline void expect_valid_part(const CappedRun& run, const std::vector<SurfacePtr>& faces, double diagonal,
                              bool planar_caps = true, const std::function<bool(const Vec3&)>& exempt = {}) {
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_EQ(t.unreferenced_vertices, 0u);
  EXPECT_GT(test::enclosed_volume(run.mesh), 0.0);
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  EXPECT_LT(test::max_vertex_distance(*run.surface, run.mesh), 1e-9 * diagonal);
  // The face each triangle lies on (the first whose function vanishes at its three corners).
  std::vector<std::vector<int>> around(run.mesh.vertex_count());
  for (const Triangle& tri : run.mesh.triangles)
    for (std::size_t f = 0; f < faces.size(); ++f) {
      bool on = true;
      for (std::uint32_t v : tri)
        on = on && std::abs(faces[f]->value(run.mesh.positions[v])) < 1e-9 * diagonal;
      if (!on) continue;
      for (std::uint32_t v : tri) around[v].push_back(static_cast<int>(f));
      break;
    }
  std::size_t crease = 0;
  for (std::size_t v = 0; v < around.size(); ++v) {
    std::vector<int> a = around[v];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    if (a.size() < 2) continue;
    ++crease;
    for (int f : a) {
      const ValueGradient g = faces[static_cast<std::size_t>(f)]->value_gradient(run.mesh.positions[v]);
      EXPECT_LT(std::abs(g.value) / g.gradient.norm(), 1e-9 * diagonal) << "vertex " << v << " face " << f;
    }
  }
  EXPECT_GT(crease, 0u);
  ASSERT_TRUE(run.stats.creases);
  if (planar_caps) {
    EXPECT_GT(run.stats.creases->caps, 0u);
  }
  EXPECT_GE(run.stats.creases->crease_vertices, crease);
  const std::vector<int> valence = test::valences(run.mesh);
  EXPECT_GE(static_cast<double>(std::count(valence.begin(), valence.end(), 6)) /
                static_cast<double>(valence.size()),
            0.90);
  // The crease path's floor: narrow corners where the cut meets the polyhedron's edges and corners keep
  // one triangle per 60 degrees (cap_wedges.hpp).
  Mesh judged = run.mesh;
  if (exempt)
    std::erase_if(judged.triangles, [&](const Triangle& tri) {
      return exempt((run.mesh.positions[tri[0]] + run.mesh.positions[tri[1]] + run.mesh.positions[tri[2]]) /
                    3.0);
    });
  EXPECT_GE(test::min_angle_degrees(judged), 25.0);
}

}  // namespace isopatch::test
