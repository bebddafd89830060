// Triply periodic surfaces cut open by boxes that do not line up with their periods (issue 35): the
// box faces meet the surface at every angle, some nearly tangent, and the box edges pass close to the
// surface. The cut must lie exactly on the box faces (the clean-up slides and merges only vertices that
// lie exactly on one face), and the default mesh must hold the quality floor there.
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include "api/cut_feature_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>

namespace isopatch {
namespace {

const std::string kGyroid = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)";
const std::string kSchwarzP = "cos(x)+cos(y)+cos(z)";
const std::string kSchwarzD =
    "sin(x)*sin(y)*sin(z)+sin(x)*cos(y)*cos(z)+cos(x)*sin(y)*cos(z)+cos(x)*cos(y)*sin(z)";

/// Boxes whose sides are not multiples of the period, drawn once at random: their faces cut the
/// surfaces at arbitrary phases.
struct Case {
  const std::string* formula;
  Box box;
};
const Case kCases[] = {
    {&kGyroid, {Vec3(-2.077, -1.494, -3.342), Vec3(1.295, 2.902, 2.181)}},
    {&kGyroid, {Vec3(-1.760, -2.834, -1.495), Vec3(2.478, 1.256, 1.794)}},
    {&kGyroid, {Vec3(-2.181, -1.591, -1.152), Vec3(2.382, 1.864, 2.692)}},
    {&kGyroid, {Vec3::Constant(-3.1), Vec3::Constant(3.1)}},
    // Four crossings within 1e-7 of one lattice point on the face y = 3.3: ears of the raw mesh.
    {&kGyroid, {Vec3(-3.05, -2.2, -1.55), Vec3(2.95, 3.3, 2.6)}},
    {&kSchwarzP, {Vec3(-1.852, -1.978, -1.676), Vec3(1.959, 3.142, 3.387)}},
    {&kSchwarzP, {Vec3(-2.231, -1.225, -3.025), Vec3(1.710, 3.434, 2.248)}},
    {&kSchwarzD, {Vec3(-1.019, -1.350, -3.198), Vec3(1.832, 2.804, 2.778)}},
    {&kSchwarzD, {Vec3(-1.200, -2.129, -2.489), Vec3(1.860, 3.119, 1.883)}},
};

/// The ends of every edge used by one triangle.
std::vector<std::uint32_t> boundary_vertices(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::uint32_t> out;
  for (const auto& [edge, count] : uses)
    if (count == 1) out.insert(out.end(), {edge.first, edge.second});
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// Whether p lies exactly (bit for bit) on a face of `box`.
bool exactly_on_face(const Vec3& p, const Box& box) {
  return (p.array() == box.lo.array()).any() || (p.array() == box.hi.array()).any();
}

Mesh mesh_case(const Case& c, int remesh_rounds) {
  const SurfacePtr surface = resolve_surface(*c.formula, c.box);
  Settings s;
  s.box = c.box;
  if (remesh_rounds >= 0) s.remesh_iterations = remesh_rounds;
  return mesh_surface(*surface, s);
}

TEST(GrazingBoxes, RawCutLiesExactlyOnTheBoxFaces) {
  // The paper's method alone: side points on a box face are put into its plane, not interpolated
  // between two corners on it ((1 - t) a + t b rounds 3.387 to 3.3870000000000005).
  for (const Case& c : kCases) {
    const Mesh mesh = mesh_case(c, 0);
    const std::vector<std::uint32_t> boundary = boundary_vertices(mesh);
    ASSERT_FALSE(boundary.empty());
    std::size_t off = 0;
    for (std::uint32_t v : boundary) off += !exactly_on_face(mesh.positions[v], c.box);
    EXPECT_EQ(off, 0u) << *c.formula << " in " << c.box.lo.transpose() << " / " << c.box.hi.transpose();
  }
}

TEST(GrazingBoxes, DefaultMeshHoldsTheFloor) {
  for (const Case& c : kCases) {
    const SurfacePtr surface = resolve_surface(*c.formula, c.box);
    const Mesh mesh = mesh_case(c, -1);
    const QualityReport q = analyze_quality(mesh, surface.get());
    SCOPED_TRACE(*c.formula + " in box " + std::to_string(c.box.lo.x()) + "..." +
                 std::to_string(c.box.hi.z()));
    EXPECT_GE(q.shape.min_angle.min, 20.0);
    EXPECT_GE(q.valence.share_6, 0.93);
    for (std::uint32_t v : boundary_vertices(mesh)) {
      const Vec3& p = mesh.positions[v];
      ASSERT_TRUE(exactly_on_face(p, c.box)) << p.transpose();
      const ValueGradient vg = surface->value_gradient(p);
      ASSERT_LE(std::abs(vg.value) / vg.gradient.norm(), 1e-9 * c.box.diagonal()) << p.transpose();
    }
  }
}

ConvexRegion below(double z) {
  return {HalfSpace{0, 0, 1, -z}};
}

TEST(CutFeatureSizes, NoneWhereTheCutIsWide) {
  // A closed sphere in its box: no cut at all. The gyroid in its own box of one period: its cut curves
  // end in the box corners and edges at good angles, which are no features.
  const Box sphere_box{Vec3::Constant(-1.2), Vec3::Constant(1.2)};
  EXPECT_TRUE(cut_feature_sizes(*resolve_surface("x^2+y^2+z^2-1", sphere_box), sphere_box, {}, 0.0375, 0.001)
                  .empty());
  EXPECT_TRUE(
      cut_feature_sizes(*resolve_surface("x^2+y^2+z^2-1", sphere_box), sphere_box, below(0.9), 0.0375, 0.001)
          .empty());
  const Box period{Vec3::Constant(-std::numbers::pi), Vec3::Constant(std::numbers::pi)};
  EXPECT_TRUE(cut_feature_sizes(*resolve_surface(kGyroid, period), period, {}, 0.098, 0.003).empty());
}

TEST(CutFeatureSizes, SmallHoleOfANearlyTangentPlane) {
  // z <= 0.9999 cuts a hole of radius 0.014 into the unit sphere, under half the edge of 0.0375.
  const Box box{Vec3::Constant(-1.2), Vec3::Constant(1.2)};
  const GradedSizes sizes =
      cut_feature_sizes(*resolve_surface("x^2+y^2+z^2-1", box), box, below(0.9999), 0.0375, 0.001);
  ASSERT_FALSE(sizes.empty());
  const double r = std::sqrt(1.0 - 0.9999 * 0.9999);
  EXPECT_LT(sizes.smallest(), 0.6 * r);  // at most 0.6 rad of the hole's circle per edge
  EXPECT_GE(sizes.smallest(), 0.001);
  EXPECT_LE(sizes.extent().hi.x(), r + 1e-9);
  EXPECT_LT(sizes.at(Vec3(r, 0, 0.9999)), 0.6 * r);    // on the hole's circle
  EXPECT_DOUBLE_EQ(sizes.at(Vec3(0, 0, -1)), 0.0375);  // far away: the edge length
  // Graded: never faster than 0.3 per unit distance.
  EXPECT_LE(sizes.at(Vec3(0.1, 0, 0.995)), sizes.smallest() + 0.3 * 0.1 + 1e-12);
}

TEST(CutFeatureSizes, MeshRefinedAtTheFeatureOnlyAndUniformKeepsOneSize) {
  const Box box{Vec3(-1.6, -1.6, -0.6), Vec3(1.6, 1.6, 0.6)};
  const std::string torus = "(x^2+y^2+z^2+1-0.16)^2-4*(x^2+y^2)";
  const SurfacePtr surface = resolve_surface(torus, box);
  Settings s;
  s.box = box;
  s.region = below(0.3999);  // shaves a slit 0.018 wide off the top of the tube
  MeshStats stats;
  const Mesh mesh = mesh_surface(*surface, s, &stats);
  ASSERT_TRUE(stats.local_sizes.has_value());
  EXPECT_GT(stats.local_sizes->added_vertices, 0u);
  EXPECT_LT(stats.local_sizes->extent.lo.z(), 0.3999 + 1e-9);
  EXPECT_GT(stats.local_sizes->extent.lo.z(), 0.3999 - 1e-9);  // all on the plane
  const QualityReport q = analyze_quality(mesh, surface.get());
  EXPECT_GE(q.shape.min_angle.min, 15.0);  // 3.6 degrees with one size
  s.uniform = true;
  MeshStats uniform_stats;
  const Mesh uniform = mesh_surface(*surface, s, &uniform_stats);
  EXPECT_FALSE(uniform_stats.local_sizes.has_value());
  EXPECT_LT(analyze_quality(uniform, surface.get()).shape.min_angle.min, q.shape.min_angle.min);
}

}  // namespace
}  // namespace isopatch
