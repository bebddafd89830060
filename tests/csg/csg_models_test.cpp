// The CSG models of issue 37 meshed along their creases (label validation: release builds only). Each
// is watertight, manifold, outward, of its Euler characteristic, free of self-intersections, with
// every vertex near a crease on both faces, angles over the floor and mostly valence 6; exact
// volumes where they are known; dihedral angles across a curved crease converging with the edge.
#include <gtest/gtest.h>

#include <isopatch/topology.hpp>

#include <cmath>
#include <ostream>
#include <sstream>
#include <string>

#include "core/triangle_angle.hpp"
#include "csg_checks.hpp"
#include "mesh_checks.hpp"
#include "self_intersection.hpp"

namespace isopatch {
namespace {

struct Model {
  const char* name;
  std::string formula;
  Box box;
  long euler;
  double volume;      ///< exact, or 0 when not known
  double edge = 0.0;  ///< edge length (0: the default)
};

double valence6_share(const Mesh& mesh) {
  const std::vector<int> v = test::valences(mesh);
  return static_cast<double>(std::count(v.begin(), v.end(), 6)) / static_cast<double>(v.size());
}

Box cube(double a) {
  return {Vec3::Constant(-a), Vec3::Constant(a)};
}

/// A plate with a 7 x 7 pattern of bolt holes: 50 primitives.
std::string bolt_plate() {
  std::string f = "max(max(abs(x)-3,abs(y)-3),abs(z)-0.2)";
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) {
      std::ostringstream hole;
      hole << "0.04-(x-(" << -2.4 + 0.8 * i << "))^2-(y-(" << -2.4 + 0.8 * j << "))^2";
      f = "max(" + f + "," + hole.str() + ")";
    }
  return f;
}

const Model kModels[] = {
    {"box", "max(max(abs(x),abs(y)),abs(z))-1", cube(1.5), 2, 8.0},
    {"box_rotated_z", "a=0.6;u=cos(a)*x-sin(a)*y;v=sin(a)*x+cos(a)*y;max(max(abs(u),abs(v)),abs(z))-1",
     cube(1.6), 2, 8.0},
    {"box_rotated_twice",
     "a=0.5;b=0.7;u=cos(a)*x-sin(a)*y;v=sin(a)*x+cos(a)*y;w=cos(b)*v-sin(b)*z;t=sin(b)*v+cos(b)*z;"
     "max(max(abs(u),abs(w)),abs(t))-1",
     cube(1.9), 2, 8.0},
    {"box_minus_cylinder", "max(max(max(abs(x),abs(y)),abs(z))-1,0.25-x^2-y^2)", cube(1.5), 0,
     8.0 - 0.5 * std::numbers::pi},
    {"sphere_and_cube", "max(x^2+y^2+z^2-1.69,max(max(abs(x),abs(y)),abs(z))-1)", cube(1.5), 2, 0.0},
    {"steinmetz_union",
     "min(min(max(y^2+z^2-1,abs(x)-1.5),max(x^2+z^2-1,abs(y)-1.5)),max(x^2+y^2-1,abs(z)-1.5))", cube(2.0), 2,
     0.0},
    {"sphere_tangent_to_box_faces", "max(x^2+y^2+z^2-1,max(max(abs(x),abs(y))-0.8,abs(z)-1))", cube(1.2), 2,
     0.0},
    {"boxes_sharing_part_of_a_face",
     "min(max(max(abs(x),abs(y)),abs(z))-1,max(max(abs(x-1.5),abs(y)),abs(z-0.3))-0.5)",
     {Vec3(-1.5, -1.5, -1.5), Vec3(2.5, 1.5, 1.5)},
     2,
     9.0},
    {"tetrahedron", "max(max(max(x+y+z-1,x-y-z-1),-x+y-z-1),-x-y+z-1)", cube(2.0), 2, 8.0 / 3.0},
    {"plate_with_narrow_chamfer", "max(max(max(abs(x)-1,abs(y)-1),abs(z)-0.2),x+z-1.17)", cube(1.5), 2,
     2.0 * 0.4 * 2.0 - 2.0 * 0.5 * 0.03 * 0.03},
    {"smooth_union_small_k",
     "k=0.1;a=max(max(abs(x),abs(y)),abs(z))-0.7;b=x^2+y^2+(z-0.7)^2-0.25;h=max(k-abs(a-b),0)/"
     "k;min(a,b)-h*h*k/4",
     {Vec3(-1.2, -1.2, -1.2), Vec3(1.2, 1.2, 1.4)},
     2,
     0.0},
    // A box and a sphere apart: the sphere is a face without a crease, cut by closed seams.
    {"box_beside_a_sphere",
     "min(max(max(abs(x),abs(y)),abs(z))-1,(x-2.5)^2+y^2+z^2-0.64)",
     {Vec3(-1.5, -1.5, -1.5), Vec3(3.5, 1.5, 1.5)},
     4,
     0.0},
    // A corner cut off by a plane, its triangle (side 0.028) narrower than the seed grid's cells (0.047):
    // the grid does not see it, the interval cover does.
    {"corner_cut_below_the_grid", "max(max(max(abs(x),abs(y)),abs(z))-1,x+y+z-2.98)", cube(1.5), 2,
     8.0 - 0.02 * 0.02 * 0.02 / 6.0},
    {"bolt_plate_50_primitives", bolt_plate(), {Vec3(-3.2, -3.2, -0.5), Vec3(3.2, 3.2, 0.5)}, -96, 0.0, 0.05},
};

void PrintTo(const Model& m, std::ostream* os) {
  *os << m.name;
}

class CsgModel : public ::testing::TestWithParam<Model> {};

TEST_P(CsgModel, IsMeshedAlongItsCreases) {
  const Model& m = GetParam();
  Settings s;
  if (m.edge > 0.0) s.edge_length = m.edge;
  const test::CsgRun run = test::mesh_csg(m.formula, m.box, s);
  ASSERT_TRUE(run.stats.creases) << m.name;
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_TRUE(t.watertight()) << m.name;
  EXPECT_TRUE(t.manifold()) << m.name;
  EXPECT_TRUE(t.consistently_oriented()) << m.name;
  EXPECT_GT(test::enclosed_volume(run.mesh), 0.0) << m.name << ": outward";
  EXPECT_EQ(t.euler_characteristic, m.euler) << m.name;
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u) << m.name;
  const double diagonal = m.box.diagonal();
  EXPECT_LT(test::max_vertex_distance(*run.surface, run.mesh), 1e-9 * diagonal) << m.name;
  const auto [residual, near] = test::crease_residual(run);
  EXPECT_GT(near, 0u) << m.name;
  EXPECT_LT(residual, 1e-9 * diagonal) << m.name;
  EXPECT_EQ(run.stats.warnings.exempt_corners, 0u) << m.name;
  // Certified: every place two faces may meet was explained. A smooth solid capped by planes (the box
  // minus a cylinder, the sphere and cube) is meshed as its cut surface closed by planar caps
  // (docs/lattices.md): its creases are the cut's boundary, no analysis of face pairs is made.
  if (run.stats.creases->caps == 0) {
    EXPECT_GT(run.stats.creases->interval_cells, 0u) << m.name;
  }
  EXPECT_EQ(run.stats.creases->uncertain_cells, 0u) << m.name;
  EXPECT_EQ(run.stats.warnings.uncertain_crease_cells, 0u) << m.name;
  EXPECT_GE(test::min_angle_degrees(run.mesh), 25.0) << m.name;
  EXPECT_GE(valence6_share(run.mesh), 0.90) << m.name;
  if (m.volume > 0.0) {
    EXPECT_NEAR(test::enclosed_volume(run.mesh) / m.volume, 1.0, 1e-3) << m.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Issue37, CsgModel, ::testing::ValuesIn(kModels),
                         [](const auto& model) { return std::string(model.param.name); });

TEST(CsgCertificate, TheCreasesOfACornerCutNarrowerThanTheSeedGridAreFoundByIntervals) {
  const test::CsgRun run = test::mesh_csg("max(max(max(abs(x),abs(y)),abs(z))-1,x+y+z-2.98)", cube(1.5));
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.creases->faces, 7u);
  EXPECT_EQ(run.stats.creases->creases, 15u);
  // The cut's three creases: the seed grid has no vertex on the cut, the cover's cells do.
  EXPECT_EQ(run.stats.creases->interval_creases, 3u);
}

TEST(CsgDihedral, TheAngleAcrossACurvedCreaseConvergesWithTheEdge) {
  // A sphere with a cylindrical hole: faces meet at 120 degrees between their normals on two circles.
  const char* formula = "max(x^2+y^2+z^2-1,0.25-x^2-y^2)";
  const Box box = cube(1.2);
  const SurfacePtr sphere = expression_surface("x^2+y^2+z^2-1", box);
  const SurfacePtr hole = expression_surface("0.25-x^2-y^2", box);
  double previous = 0.0;
  for (const double h : {0.08, 0.04, 0.02}) {
    Settings s;
    s.edge_length = h;
    const double error = test::dihedral_error(test::mesh_csg(formula, box, s).mesh, *sphere, *hole, 1e-9);
    ASSERT_GT(error, 0.0);
    if (previous > 0.0) {
      EXPECT_LT(error, 0.65 * previous) << h;  // halves, within the rounding of segment counts
    }
    previous = error;
  }
}

}  // namespace
}  // namespace isopatch

namespace isopatch {
namespace {

TEST(CsgExemptCorners, AWedgeOfTwentyDegreesIsCountedAndOnlyItsCornersMissTheFloor) {
  // A prism whose top meets its bottom at 20 degrees (tan 20 = 0.364): its end faces have a 20 degree
  // corner each, where triangles cannot reach 25 degrees.
  const std::string formula = "max(max(abs(x)-1,abs(y)-1),max(-z,z-0.364*(x+0.8)))";
  const Box box{Vec3(-1.5, -1.5, -0.5), Vec3(1.5, 1.5, 1.2)};
  const test::CsgRun run = test::mesh_csg(formula, box);
  ASSERT_TRUE(run.stats.creases);
  EXPECT_EQ(run.stats.warnings.exempt_corners, 2u);
  const TopologyReport t = analyze_topology(run.mesh);
  EXPECT_TRUE(t.watertight() && t.manifold() && t.consistently_oriented());
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(test::count_self_intersections(run.mesh, 10), 0u);
  EXPECT_NEAR(test::enclosed_volume(run.mesh) / (2.0 * 0.5 * 1.8 * 0.364 * 1.8), 1.0, 1e-9);
  const double h = target_sizes(Settings{}, box).largest;
  for (const Triangle& tri : run.mesh.triangles) {
    const Vec3 a = run.mesh.positions[tri[0]], b = run.mesh.positions[tri[1]], c = run.mesh.positions[tri[2]];
    if (smallest_angle(a, b, c) >= 25.0) continue;
    const Vec3 centre = (a + b + c) / 3.0;
    const double to_corner =
        std::min((centre - Vec3(-0.8, 1.0, 0.0)).norm(), (centre - Vec3(-0.8, -1.0, 0.0)).norm());
    EXPECT_LT(to_corner, h) << "a small angle away from the exempt corners";
  }
}

}  // namespace
}  // namespace isopatch
