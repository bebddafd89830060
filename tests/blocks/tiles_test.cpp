// Tiles of a box cut by planes (isopatch/tiles.hpp): the faces' curves shared bit for bit by the tiles
// beside them; tiles meshed apart, watertight across the planes, on f = 0, of one process's topology
// and nearly its quality; the same bytes in any order.
#include <gtest/gtest.h>

#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/metrics.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/tiles.hpp>
#include <isopatch/topology.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "split_checks.hpp"

namespace isopatch {
namespace {

/// A surface meshed tile by tile: every face's curves first, then every tile's base and refinement.
struct TiledMesh {
  TileGrid grid;
  std::vector<FaceCurves> faces;
  std::vector<TileMesh> tiles;

  TiledMesh(const Surface& surface, const Settings& settings, const std::array<int, 3>& counts, int level,
            double edge, bool reverse = true)
      : grid(clear_tile_grid(surface, *settings.box, counts, 0.4 * edge * level)) {
    const double spacing = edge * level;
    const std::vector<TileFace> all = grid_faces(grid);
    for (const TileFace& f : all) faces.push_back(face_curves(surface, grid, f, spacing));
    for (int i = 0; i < grid.tile_count(); ++i) {
      const int t = reverse ? grid.tile_count() - 1 - i : i;
      const auto cell = grid.tile(t);
      std::vector<FaceCurves> own;
      for (const TileFace& f : tile_faces(cell))
        own.push_back(faces[static_cast<std::size_t>(std::find(all.begin(), all.end(), f) - all.begin())]);
      const Mesh base = tile_base(surface, settings, grid, cell, own, spacing);
      tiles.push_back(refine_tile(surface, settings, grid, cell, base, level));
    }
  }
};

Settings gyroid_settings() {
  Settings s;
  s.box = Box{Vec3::Constant(-3.0), Vec3::Constant(3.0)};
  s.edge_length = 0.1;
  s.refine = 2;
  return s;
}

/// The smallest angle (degrees) of the triangles with a corner within `width` of an inner plane of the
/// grid (the seam band: one base edge) and of the others.
struct BandAngles {
  double band = 180.0, rest = 180.0;
};

BandAngles band_angles(const Mesh& mesh, const TileGrid& grid, double width) {
  const auto on_plane = [&](const Vec3& p) {
    for (int a = 0; a < 3; ++a)
      for (int i = 1; i < grid.counts[static_cast<std::size_t>(a)]; ++i)
        if (std::abs(p[a] - grid.plane(a, i)) < width) return true;
    return false;
  };
  BandAngles out;
  for (const Triangle& t : mesh.triangles) {
    double smallest = 180.0;
    bool band = false;
    for (int c = 0; c < 3; ++c) {
      const Vec3& a = mesh.positions[t[static_cast<std::size_t>(c)]];
      const Vec3 u = mesh.positions[t[static_cast<std::size_t>((c + 1) % 3)]] - a;
      const Vec3 v = mesh.positions[t[static_cast<std::size_t>((c + 2) % 3)]] - a;
      smallest = std::min(smallest, std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / M_PI);
      band = band || on_plane(a);
    }
    (band ? out.band : out.rest) = std::min(band ? out.band : out.rest, smallest);
  }
  return out;
}

/// The number of edges of one triangle whose two ends lie on a face of `box` (exactly).
std::size_t boundary_edges_on_box(const Mesh& mesh, const Box& box) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const Triangle& t : mesh.triangles)
    for (std::size_t c = 0; c < 3; ++c) ++count[std::minmax(t[c], t[(c + 1) % 3])];
  const auto on_box = [&](const Vec3& p) {
    return (p.array() == box.lo.array()).any() || (p.array() == box.hi.array()).any();
  };
  std::size_t n = 0;
  for (const auto& [edge, k] : count)
    if (k == 1 && on_box(mesh.positions[edge.first]) && on_box(mesh.positions[edge.second])) ++n;
  return n;
}

TEST(TileGrid, PlanesAreSharedAndTilesCoverTheDomain) {
  const TileGrid grid = make_tile_grid(Box{Vec3(0, 0, 0), Vec3(1, 2, 3)}, {3, 2, 1});
  EXPECT_EQ(grid.tile_count(), 6);
  EXPECT_EQ(grid.plane(0, 0), 0.0);
  EXPECT_EQ(grid.plane(0, 3), 1.0);
  for (int t = 0; t < grid.tile_count(); ++t) EXPECT_EQ(grid.tile_number(grid.tile(t)), t);
  EXPECT_EQ(grid.tile_box({0, 0, 0}).hi.x(), grid.tile_box({1, 0, 0}).lo.x());
  EXPECT_EQ(grid_faces(grid).size(), 4U * 2 + 3U * 3 + 2U * 6);
  EXPECT_THROW(make_tile_grid(Box{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {0, 1, 1}), SettingError);
  EXPECT_THROW(make_tile_grid(Box{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {64, 64, 2}), SettingError);
  EXPECT_THROW(tile_counts(Box{Vec3(0, 0, 0), Vec3(1, 1, 1)}, 0), SettingError);
  const auto counts = tile_counts(Box{Vec3(0, 0, 0), Vec3(4, 1, 1)}, 4);
  EXPECT_EQ(counts, (std::array<int, 3>{4, 1, 1}));
}

TEST(FaceCurves, CrossingsOnASideAreTheSameInEveryFaceBesideIt) {
  const SurfacePtr gyroid = catalogue_surface("gyroid");
  const TileGrid grid = make_tile_grid(Box{Vec3::Constant(-3.0), Vec3::Constant(3.0)}, {2, 2, 2});
  // The lattice edge along z at x = 0, y = 0, lower cell: a side of faces on the x and y planes.
  const FaceCurves x = face_curves(*gyroid, grid, {0, 1, {1, 0}}, 0.2);
  const FaceCurves y = face_curves(*gyroid, grid, {1, 1, {0, 1}}, 0.2);
  const auto on_edge = [](const FaceCurves& f) {
    std::vector<std::array<double, 3>> out;
    for (const auto& curve : f.curves)
      for (const std::uint32_t p : {curve.front(), curve.back()}) {
        const Vec3& q = f.points[p];
        if (q.x() == 0.0 && q.y() == 0.0 && q.z() <= 0.0) out.push_back({q.x(), q.y(), q.z()});
      }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  ASSERT_FALSE(on_edge(x).empty());
  EXPECT_EQ(on_edge(x), on_edge(y));
  for (const FaceCurves* f : {&x, &y})
    for (const Vec3& p : f->points) {
      EXPECT_LT(std::abs(gyroid->value(p)), 1e-9);
      EXPECT_EQ(p[f->face.axis], 0.0);
    }
  EXPECT_THROW(face_curves(*gyroid, grid, {0, 1, {1, 0}}, 0.0), SettingError);
}

TEST(Tiles, EightTilesOfAGyroidAreWatertightOnTheSurfaceAndNearOneProcess) {
  const SurfacePtr gyroid = catalogue_surface("gyroid");
  const Settings settings = gyroid_settings();
  const TiledMesh tiled(*gyroid, settings, {2, 2, 2}, 2, 0.1);
  std::size_t band = 0;
  for (const TileMesh& t : tiled.tiles) {
    EXPECT_EQ(t.failed_points, 0U) << "tile " << t.tile;
    band += t.seam_band_vertices;
  }
  const Mesh mesh = assemble_tiles(tiled.grid, tiled.tiles);
  const QualityReport q = analyze_quality(mesh, gyroid.get());
  const QualityReport one = analyze_quality(mesh_surface(*gyroid, settings), gyroid.get());
  const BandAngles angles = band_angles(mesh, tiled.grid, 0.2);
  std::printf(
      "tiles: %zu vertices, valence 6 %.4f, smallest angle %.2f off the seams, %.2f on them (%zu "
      "vertices); one process: %zu, %.4f, %.2f\n",
      mesh.vertex_count(), q.valence.share_6, angles.rest, angles.band, band, one.topology.vertices,
      one.valence.share_6, one.shape.min_angle.min);
  EXPECT_EQ(q.topology.non_manifold_edges, 0U);
  // Open only where the box cuts the gyroid (as one process): no edge of one triangle on an inner plane.
  EXPECT_GT(one.topology.boundary_edges, 0U);
  EXPECT_EQ(q.topology.boundary_edges, boundary_edges_on_box(mesh, *settings.box));
  test::expect_one_process_topology(q, one);
  EXPECT_GT(q.valence.share_6, one.valence.share_6 - 0.01);
  EXPECT_GT(angles.rest, 20.0);
  EXPECT_GT(angles.band, 15.0);
  EXPECT_GT(band, 0U);
}

TEST(Tiles, TheSameBytesInAnyOrderAndForAnyThreadCount) {
  const SurfacePtr gyroid = catalogue_surface("gyroid");
  Settings settings = gyroid_settings();
  settings.edge_length = 0.15;
  const Mesh reverse = assemble_tiles(TiledMesh(*gyroid, settings, {2, 1, 2}, 2, 0.15).grid,
                                      TiledMesh(*gyroid, settings, {2, 1, 2}, 2, 0.15).tiles);
  settings.threads = 1;
  const TiledMesh forward(*gyroid, settings, {2, 1, 2}, 2, 0.15, false);
  const Mesh one_thread = assemble_tiles(forward.grid, forward.tiles);
  EXPECT_GT(one_thread.vertex_count(), 1000U);
  EXPECT_EQ(one_thread.positions, reverse.positions);
  EXPECT_EQ(one_thread.triangles, reverse.triangles);
}

TEST(Tiles, ASphereInManyTilesIsClosedWithCapsAndEmptyTiles) {
  // Planes at about +-0.3 and +-0.9: the caps beyond 0.9 are small disks whose tiles hold little else;
  // most of the 125 tiles hold nothing.
  const SurfacePtr sphere = catalogue_surface("sphere");
  Settings settings;
  settings.box = Box{Vec3::Constant(-1.5), Vec3::Constant(1.5)};
  settings.edge_length = 0.08;
  settings.refine = 2;
  const TiledMesh tiled(*sphere, settings, {5, 5, 5}, 2, 0.08);
  const Mesh mesh = assemble_tiles(tiled.grid, tiled.tiles);
  std::size_t empty = 0;
  for (const TileMesh& t : tiled.tiles) empty += t.mesh.triangles.empty() ? 1 : 0;
  EXPECT_GT(empty, 50U);
  const QualityReport q = analyze_quality(mesh, sphere.get());
  EXPECT_TRUE(q.topology.watertight());
  EXPECT_TRUE(q.topology.outward_oriented());
  EXPECT_EQ(q.topology.euler_characteristic, 2);
  EXPECT_EQ(q.topology.components.size(), 1U);
  EXPECT_EQ(q.topology.duplicate_vertices, 0U);
  EXPECT_EQ(q.self_intersections.pairs, 0U);
  ASSERT_TRUE(q.accuracy);
  EXPECT_LT(q.accuracy->vertex_distance.max, 1e-9);
  const BandAngles angles = band_angles(mesh, tiled.grid, 0.16);
  std::printf("sphere in tiles: smallest angle %.2f off the seams, %.2f on them\n", angles.rest, angles.band);
  EXPECT_GT(angles.rest, 20.0);
  EXPECT_GT(angles.band, 10.0);  // slivers where a plane nearly touches the sphere near a tile's edge
  EXPECT_GT(q.valence.share_6, 0.9);
}

TEST(Tiles, RefuseWhatTheyDoNotTake) {
  const SurfacePtr gyroid = catalogue_surface("gyroid");
  Settings settings = gyroid_settings();
  const TileGrid grid = clear_tile_grid(*gyroid, *settings.box, {2, 1, 1}, 0.08);
  std::vector<FaceCurves> faces;
  for (const TileFace& f : tile_faces({0, 0, 0})) faces.push_back(face_curves(*gyroid, grid, f, 0.2));
  EXPECT_THROW(tile_base(*gyroid, settings, grid, {0, 0, 0}, faces, 0.3), InputError);  // other spacing
  EXPECT_THROW(tile_base(*gyroid, settings, grid, {1, 0, 0}, faces, 0.2), InputError);  // other tile
  EXPECT_THROW(tile_base(*gyroid, settings, grid, {0, 0, 0}, std::span(faces).first(5), 0.2), InputError);
  Settings mc = settings;
  mc.method = Method::MarchingCubes;
  EXPECT_THROW(plan_tiles(*gyroid, mc, 8), SettingError);
  Settings bound = settings;
  bound.max_error = 0.01;
  EXPECT_THROW(plan_tiles(*gyroid, bound, 8), SettingError);
  EXPECT_THROW(plan_tiles(*gyroid, settings, 0), SettingError);
  const Mesh base = tile_base(*gyroid, settings, grid, {0, 0, 0}, faces, 0.2);
  EXPECT_THROW(refine_tile(*gyroid, settings, grid, {0, 0, 0}, base, 0), InputError);
  const TileMesh one = refine_tile(*gyroid, settings, grid, {0, 0, 0}, base, 2);
  // A tile missing, a tile twice, a tile without its neighbour's seam.
  EXPECT_THROW(assemble_tiles(grid, std::span(&one, 1)), InputError);
  const std::vector<TileMesh> twice{one, one};
  EXPECT_THROW(assemble_tiles(grid, twice), InputError);
  TileMesh empty;
  empty.tile = 1;
  empty.kept = true;
  const std::vector<TileMesh> unmatched{one, empty};
  EXPECT_THROW(assemble_tiles(grid, unmatched), InputError);
}

TEST(Tiles, PlansKeepTheirPlanesClearOfTheSurfaceAtTheCorners) {
  const SurfacePtr gyroid = catalogue_surface("gyroid");
  Settings settings = gyroid_settings();
  const TilePlan plan = plan_tiles(*gyroid, settings, 8);
  EXPECT_EQ(plan.level, 2);
  EXPECT_EQ(plan.grid.counts, (std::array<int, 3>{2, 2, 2}));
  // The gyroid passes through the origin, the even grid's middle corner: the planes moved off it.
  const Vec3 corner(plan.grid.plane(0, 1), plan.grid.plane(1, 1), plan.grid.plane(2, 1));
  const ValueGradient vg = gyroid->value_gradient(corner);
  EXPECT_GE(std::abs(vg.value) / vg.gradient.norm(), 0.4 * plan.spacing());
  for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(plan.grid.plane(a, 1)), 0.2 * 3.0 + 1e-12);
  EXPECT_GT(plan.estimated_vertices, 1000.0);
}

}  // namespace
}  // namespace isopatch
