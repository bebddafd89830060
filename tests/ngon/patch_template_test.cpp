#include "ngon/patch_template.hpp"

#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <thread>
#include <utility>
#include <vector>

namespace isopatch {
namespace {

using Kind = VertexTag::Kind;

std::size_t expected_vertices(int n, int r) {
  if (n == 3) return static_cast<std::size_t>((r + 1) * (r + 2) / 2);
  if (n == 4) return static_cast<std::size_t>((r + 1) * (r + 1));
  return static_cast<std::size_t>(1 + n * r * (r + 1) / 2);
}

std::size_t expected_triangles(int n, int r) {
  return static_cast<std::size_t>(n == 3 ? r * r : n == 4 ? 2 * r * r : n * r * r);
}

/// Smallest interior angle (degrees) of any template triangle in the domain.
double min_angle_degrees(const PatchTemplate& tpl) {
  double smallest = 180.0;
  for (const auto& tri : tpl.triangles()) {
    for (int c = 0; c < 3; ++c) {
      const Vec2 a =
          tpl.point(tri[static_cast<std::size_t>((c + 1) % 3)]) - tpl.point(tri[static_cast<std::size_t>(c)]);
      const Vec2 b =
          tpl.point(tri[static_cast<std::size_t>((c + 2) % 3)]) - tpl.point(tri[static_cast<std::size_t>(c)]);
      smallest = std::min(smallest, std::atan2(std::abs(cross(a, b)), a.dot(b)) * 180.0 / std::numbers::pi);
    }
  }
  return smallest;
}

/// Every template triangle is similar to a triangle of the coarsest layout: the equilateral lattice
/// triangle (n = 3), half a square (n = 4), or the fan triangle (centre, V_k, V_{k+1}) whose angles are
/// 360/n at the centre and 90 - 180/n at the corners (n >= 5). So the smallest angle is known exactly.
double expected_min_angle_degrees(int n) {
  if (n == 3) return 60.0;
  if (n == 4) return 45.0;
  return std::min(360.0 / n, 90.0 - 180.0 / n);
}

void check_template(const PatchTemplate& tpl) {
  const int n = tpl.sides();
  const int r = tpl.resolution();
  const Domain& domain = tpl.domain();
  SCOPED_TRACE("n=" + std::to_string(n) + " r=" + std::to_string(r));
  const auto nv = static_cast<int>(tpl.vertex_count());
  ASSERT_EQ(tpl.vertex_count(), expected_vertices(n, r));
  ASSERT_EQ(tpl.triangle_count(), expected_triangles(n, r));
  ASSERT_EQ(tpl.tags().size(), tpl.vertex_count());
  ASSERT_EQ(tpl.lambdas().size(), tpl.vertex_count() * static_cast<std::size_t>(n));

  // Triangles: valid, counter-clockwise, non-degenerate; they tile the polygon exactly.
  double polygon_area = 0.0, tiled_area = 0.0;
  for (int k = 0; k < n; ++k) polygon_area += cross(domain.vertex(k), domain.vertex(k + 1)) / 2;
  std::map<std::pair<int, int>, int> directed;  // half-edge -> count
  for (const auto& tri : tpl.triangles()) {
    for (int v : tri) ASSERT_TRUE(v >= 0 && v < nv);
    ASSERT_TRUE(tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]);
    const double area =
        cross(tpl.point(tri[1]) - tpl.point(tri[0]), tpl.point(tri[2]) - tpl.point(tri[0])) / 2;
    EXPECT_GT(area, 0.0);
    tiled_area += area;
    for (int c = 0; c < 3; ++c)
      ++directed[{tri[static_cast<std::size_t>(c)], tri[static_cast<std::size_t>((c + 1) % 3)]}];
  }
  EXPECT_NEAR(tiled_area, polygon_area, 1e-12);
  EXPECT_NEAR(min_angle_degrees(tpl), expected_min_angle_degrees(n), 1e-9);

  // Oriented manifold disk: no half-edge twice; the unpaired half-edges are the boundary, exactly the
  // consecutive entries of side_vertices, so they form one ccw loop of n r edges.
  std::set<std::pair<int, int>> edges;
  std::set<std::pair<int, int>> boundary;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    edges.insert(std::minmax(edge.first, edge.second));
    if (!directed.contains({edge.second, edge.first})) boundary.insert(edge);
  }
  EXPECT_EQ(static_cast<long>(nv) - static_cast<long>(edges.size()) + static_cast<long>(tpl.triangle_count()),
            1);
  EXPECT_EQ(boundary.size(), static_cast<std::size_t>(n * r));
  std::set<std::pair<int, int>> loop;
  for (int k = 0; k < n; ++k) {
    const auto side = tpl.side_vertices(k);
    ASSERT_EQ(side.size(), static_cast<std::size_t>(r + 1));
    for (int i = 0; i < r; ++i)
      loop.insert({side[static_cast<std::size_t>(i)], side[static_cast<std::size_t>(i + 1)]});
    EXPECT_EQ(side.back(), tpl.side_vertices(k + 1).front());
    EXPECT_EQ(tpl.corner(k), side.front());
  }
  EXPECT_EQ(boundary, loop);

  // Tags: n corners exactly at V_k, n (r-1) side vertices exactly at side_point(k, i, r), as listed
  // by side_vertices; everything else interior.
  int corners = 0, side_count = 0;
  for (int v = 0; v < nv; ++v) {
    const VertexTag& tag = tpl.tag(v);
    if (tag.kind == Kind::Corner) {
      ++corners;
      ASSERT_TRUE(tag.side >= 0 && tag.side < n);
      EXPECT_EQ(tpl.point(v), domain.vertex(tag.side));
      EXPECT_EQ(tpl.side_vertices(tag.side).front(), v);
      EXPECT_EQ(tpl.side_vertices(tag.side - 1).back(), v);
    } else if (tag.kind == Kind::Side) {
      ++side_count;
      ASSERT_TRUE(tag.side >= 0 && tag.side < n);
      ASSERT_TRUE(tag.index >= 1 && tag.index <= r - 1);
      EXPECT_EQ(tpl.point(v), domain.side_point(tag.side, tag.index, r));
      EXPECT_EQ(tpl.side_vertices(tag.side)[static_cast<std::size_t>(tag.index)], v);
    } else {
      EXPECT_EQ(tag.side, -1);
    }
  }
  EXPECT_EQ(corners, n);
  EXPECT_EQ(side_count, n * (r - 1));

  // Valences: interior 6, the ring centre n.
  std::vector<int> valence(static_cast<std::size_t>(nv), 0);
  for (const auto& [a, b] : edges)
    ++valence[static_cast<std::size_t>(a)], ++valence[static_cast<std::size_t>(b)];
  for (int v = 0; v < nv; ++v) {
    if (tpl.tag(v).kind != Kind::Interior) continue;
    EXPECT_EQ(valence[static_cast<std::size_t>(v)], v == tpl.centre() ? n : 6) << "vertex " << v;
  }
  if (n >= 5) {
    ASSERT_TRUE(tpl.centre() >= 0 && tpl.centre() < nv);
    EXPECT_EQ(tpl.tag(tpl.centre()).kind, Kind::Interior);
    EXPECT_EQ(tpl.point(tpl.centre()), Vec2::Zero());
  } else {
    EXPECT_EQ(tpl.centre(), -1);
  }

  // Coordinates: barycentric at every vertex; exact from the tag on the boundary, and equal to a
  // direct evaluation everywhere.
  std::vector<double> direct(static_cast<std::size_t>(n));
  for (int v = 0; v < nv; ++v) {
    const auto lambda = tpl.lambda(v);
    ASSERT_EQ(lambda.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(lambda.data(), tpl.lambdas().data() + static_cast<std::size_t>(v * n));
    double sum = 0.0;
    Vec2 x = Vec2::Zero();
    for (int k = 0; k < n; ++k) {
      EXPECT_GE(lambda[static_cast<std::size_t>(k)], 0.0);
      sum += lambda[static_cast<std::size_t>(k)];
      x += lambda[static_cast<std::size_t>(k)] * domain.vertex(k);
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_LT((x - tpl.point(v)).norm(), 1e-14);
    barycentric_coordinates(domain, tpl.point(v), tpl.coordinates(), direct);
    for (int k = 0; k < n; ++k)
      EXPECT_NEAR(lambda[static_cast<std::size_t>(k)], direct[static_cast<std::size_t>(k)], 1e-14);
    const VertexTag& tag = tpl.tag(v);
    if (tag.kind == Kind::Interior) continue;
    const double t = tag.kind == Kind::Corner ? 0.0 : static_cast<double>(tag.index) / r;
    for (int k = 0; k < n; ++k) {
      const double expected = k == tag.side ? 1.0 - t : k == domain.wrap(tag.side + 1) ? t : 0.0;
      EXPECT_EQ(lambda[static_cast<std::size_t>(k)], expected);
    }
  }
}

TEST(PatchTemplate, AllSideCountsAndSmallResolutionsAreValidDisks) {
  for (int n = 3; n <= 16; ++n) {
    for (int r = 1; r <= 10; ++r) check_template(PatchTemplate(n, r, CoordinateKind::Wachspress));
  }
}

TEST(PatchTemplate, MeanValueTemplatesAreValidToo) {
  for (int n = 3; n <= 16; ++n) check_template(PatchTemplate(n, 6, CoordinateKind::MeanValue));
}

TEST(PatchTemplate, LargestResolutionHasTheDocumentedCounts) {
  for (int n : {3, 4, 7, 12}) {
    const auto tpl = patch_template(n, PatchTemplate::kMaxResolution, CoordinateKind::Wachspress);
    EXPECT_EQ(tpl->vertex_count(), expected_vertices(n, 64));
    EXPECT_EQ(tpl->triangle_count(), expected_triangles(n, 64));
    EXPECT_EQ(tpl->side_vertices(n - 1).back(), tpl->corner(0));
  }
}

TEST(PatchTemplate, MinimumDomainAngleDoesNotShrinkWithResolution) {
  // 30 degrees (n = 12) is the worst case of all layouts, at every resolution.
  for (int n = 3; n <= 12; ++n) {
    const double angle = min_angle_degrees(*patch_template(n, 64, CoordinateKind::Wachspress));
    EXPECT_NEAR(angle, expected_min_angle_degrees(n), 1e-9) << "n=" << n;
    EXPECT_GE(angle, 30.0 - 1e-9);
    RecordProperty("min_angle_n" + std::to_string(n), std::to_string(angle));
  }
  // The patches of general convex cells have up to 16 sides: the centre's 360 / n, down to 22.5 degrees.
  for (int n = 13; n <= 16; ++n) {
    const double angle = min_angle_degrees(*patch_template(n, 64, CoordinateKind::Wachspress));
    EXPECT_NEAR(angle, expected_min_angle_degrees(n), 1e-9) << "n=" << n;
    EXPECT_GE(angle, 22.5 - 1e-9);
  }
}

TEST(PatchTemplate, RejectsOutOfRangeSidesAndResolutions) {
  for (int r : {-1, 0, 65, 1000}) {
    EXPECT_THROW(PatchTemplate(5, r, CoordinateKind::Wachspress), InputError) << r;
    EXPECT_THROW(patch_template(5, r, CoordinateKind::Wachspress), InputError) << r;
  }
  for (int n : {0, 2, 17}) {
    EXPECT_THROW(PatchTemplate(n, 4, CoordinateKind::Wachspress), InputError) << n;
    EXPECT_THROW(patch_template(n, 4, CoordinateKind::MeanValue), InputError) << n;
  }
}

TEST(PatchTemplate, CacheReturnsOneSharedTemplatePerKey) {
  const auto a = patch_template(6, 5, CoordinateKind::Wachspress);
  EXPECT_EQ(a, patch_template(6, 5, CoordinateKind::Wachspress));
  const auto b = patch_template(6, 5, CoordinateKind::MeanValue);
  EXPECT_NE(a, b);
  EXPECT_EQ(b->coordinates(), CoordinateKind::MeanValue);
  EXPECT_EQ(a->sides(), 6);
  EXPECT_EQ(a->resolution(), 5);
  EXPECT_NE(a, patch_template(6, 4, CoordinateKind::Wachspress));
}

TEST(PatchTemplate, CacheIsSafeUnderConcurrentFirstUse) {
  constexpr int kThreads = 4;
  std::vector<std::vector<std::shared_ptr<const PatchTemplate>>> seen(kThreads);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back([&seen, i] {
      for (int n = 3; n <= 16; ++n)
        seen[static_cast<std::size_t>(i)].push_back(patch_template(n, 13, CoordinateKind::MeanValue));
    });
  }
  for (auto& thread : threads) thread.join();
  for (int i = 1; i < kThreads; ++i) EXPECT_EQ(seen[static_cast<std::size_t>(i)], seen[0]);
  for (int n = 3; n <= 16; ++n) EXPECT_EQ(seen[0][static_cast<std::size_t>(n - 3)]->sides(), n);
}

}  // namespace
}  // namespace isopatch
