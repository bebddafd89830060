#pragma once
// What every whole-surface mesh of the pipeline must be, shared by the remesh tests: closed, manifold,
// oriented, one component of the expected genus, free of self-intersections, vertices on f = 0,
// valence 6 >= 90% and no angle under 20 degrees.

#include <isopatch/metrics.hpp>
#include <isopatch/surface.hpp>

#include <gtest/gtest.h>

#include "mesh_checks.hpp"
#include "self_intersection.hpp"
#include "test_surfaces.hpp"

namespace isopatch::test {

/// The test torus as a SurfacePtr (*)(): the form the parameterised cases take.
inline SurfacePtr default_torus() {
  return torus();
}

/// Checks `mesh` of `s` (with its report `q`) against the floor above.
inline void expect_floor(const Mesh& mesh, const Surface& s, const QualityReport& q, int genus) {
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_TRUE(q.topology.manifold());
  EXPECT_TRUE(q.topology.consistently_oriented());
  EXPECT_EQ(q.topology.components.size(), 1u);
  EXPECT_EQ(q.topology.genus, genus);
  EXPECT_EQ(count_self_intersections(mesh), 0u);
  EXPECT_LT(max_vertex_distance(s, mesh), 1e-9 * s.box().diagonal());
  EXPECT_GE(q.valence.share_6, 0.90);
  EXPECT_GE(q.shape.min_angle.min, 20.0);
}

}  // namespace isopatch::test
