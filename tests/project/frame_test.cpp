// Every closed catalogue surface meshed in a rotated frame (Settings::frame, issue 21) against the
// same surface in the coordinate axes at the same edge length: closed, manifold, outward, of the right
// genus and component count, free of self-intersections, valence 6 >= 90%, smallest angle >= 20
// degrees, vertices on f = 0, and H nRMS within 1.5 times the unrotated mesh's.
#include <isopatch/catalogue.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "self_intersection.hpp"

namespace isopatch {
namespace {

struct Measured {
  std::size_t vertices = 0;
  double h_nrms = 0.0;
};

Measured check(const Surface& f, const CatalogueEntry& e, const Settings& s) {
  const Mesh mesh = mesh_surface(f, s);
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.outward_oriented());
  EXPECT_EQ(t.components.size(), static_cast<std::size_t>(e.components));
  EXPECT_EQ(t.genus, e.genus * e.components);
  EXPECT_EQ(test::count_self_intersections(mesh), 0u);
  const QualityReport q = analyze_quality(mesh, &f);
  EXPECT_GE(q.valence.share_6, 0.9);
  EXPECT_GE(q.shape.min_angle.min, 20.0);
  EXPECT_LE(q.accuracy->vertex_distance.max, 1e-10 * e.box.diagonal());
  return {mesh.vertex_count(), q.accuracy->mean_curvature.nrms};
}

TEST(Frame, ClosedCatalogueSurfacesInARotatedFrame) {
  for (const CatalogueEntry& e : catalogue()) {
    if (!e.closed || !e.smooth) continue;
    SCOPED_TRACE(std::string(e.name));
    const SurfacePtr f = resolve_surface(std::string(e.name), std::nullopt, {});
    Settings s;
    s.edge_length = e.box.size().maxCoeff() / 48.0;
    const Measured plain = check(*f, e, s);
    s.frame = Frame{30.0, 20.0, 10.0};
    const Measured rotated = check(*f, e, s);
    std::printf("%-13s vertices %6zu / %6zu  H nRMS %.5f / %.5f\n", std::string(e.name).c_str(),
                plain.vertices, rotated.vertices, plain.h_nrms, rotated.h_nrms);
    // The same edge length gives about the same vertex count, and a comparable curvature error.
    EXPECT_NEAR(static_cast<double>(rotated.vertices) / static_cast<double>(plain.vertices), 1.0, 0.2);
    EXPECT_LE(rotated.h_nrms, 1.5 * plain.h_nrms);
  }
}

TEST(Frame, OpenSurfaceKeepsItsCutOnTheBox) {
  // The gyroid leaves its box: in a rotated frame the box's planes become the region, so the mesh
  // stays in the box and its cut lies on the box faces.
  const CatalogueEntry* e = find_in_catalogue("gyroid");
  ASSERT_NE(e, nullptr);
  const SurfacePtr f = resolve_surface("gyroid", std::nullopt, {});
  Settings s;
  s.edge_length = e->box.size().maxCoeff() / 24.0;
  s.frame = Frame{30.0, 20.0, 10.0};
  const Mesh mesh = mesh_surface(*f, s);
  const double tol = 1e-12 * e->box.diagonal();
  for (const Vec3& p : mesh.positions) EXPECT_TRUE(e->box.contains(p, tol));
  const TopologyReport t = analyze_topology(mesh);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_GT(t.boundary_edges, 0u);
}

}  // namespace
}  // namespace isopatch
