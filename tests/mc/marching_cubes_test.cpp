// The marching cubes mesher on the benchmark surfaces and on the cases that break naive versions:
// lattice points exactly on the surface, clipping by the box, NaN, no surface, limits.
#include "test_surfaces.hpp"

#include <isopatch/error.hpp>
#include <isopatch/marching_cubes.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace isopatch {
namespace {

struct Expected {
  const char* name;
  SurfacePtr (*make)();
  int genus;
};

SurfacePtr unit_sphere() {
  return test::sphere();
}
SurfacePtr default_torus() {
  return test::torus();
}

const Expected kSurfaces[] = {
    {"sphere", unit_sphere, 0},
    {"torus", default_torus, 1},
    {"tanglecube", test::tanglecube, 5},
    {"genus2", test::genus2, 2},
};

void expect_closed_outward(const Mesh& mesh, int genus, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_NO_THROW(mesh.validate());
  const TopologyReport r = analyze_topology(mesh);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_TRUE(r.outward_oriented());
  EXPECT_EQ(r.unreferenced_vertices, 0u);
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_GT(r.components[0].volume, 0.0);
  EXPECT_EQ(r.components[0].genus, genus);
}

// Largest |f| / |grad f| over the vertices.
double max_distance(const Surface& s, const Mesh& mesh) {
  double worst = 0.0;
  for (const Vec3& p : mesh.positions) {
    const ValueGradient vg = s.value_gradient(p);
    worst = std::max(worst, std::abs(vg.value) / vg.gradient.norm());
  }
  return worst;
}

TEST(MarchingCubes, BenchmarkSurfacesAreClosedOrientedWithTheRightGenus) {
  for (const Expected& e : kSurfaces)
    for (int n : {32, 64}) {
      const SurfacePtr s = e.make();
      Settings settings;
      settings.grid = n;
      MeshStats stats;
      const Mesh mesh = marching_cubes(*s, settings, &stats);
      const std::string what = std::string(e.name) + " N=" + std::to_string(n);
      expect_closed_outward(mesh, e.genus, what);
      EXPECT_LE(max_distance(*s, mesh), 1e-10 * s->box().diagonal()) << what;
      EXPECT_EQ(stats.vertices, mesh.vertex_count());
      EXPECT_EQ(stats.triangles, mesh.triangle_count());
      const McGrid grid = marching_cubes_grid(s->box(), settings);
      const std::uint64_t lattice =
          std::uint64_t(grid.cells[0] + 1) * (grid.cells[1] + 1) * (grid.cells[2] + 1);
      EXPECT_GT(stats.value_evaluations, lattice) << what;  // grid samples plus root finding
      EXPECT_GE(stats.seconds, 0.0);
    }
}

TEST(MarchingCubes, LinearEdgesGiveValidMeshesToo) {
  for (const Expected& e : kSurfaces) {
    const SurfacePtr s = e.make();
    Settings settings;
    settings.grid = 48;
    settings.edge_root = EdgeRoot::Linear;
    MeshStats stats;
    const Mesh mesh = marching_cubes(*s, settings, &stats);
    expect_closed_outward(mesh, e.genus, e.name);
    const McGrid grid = marching_cubes_grid(s->box(), settings);
    EXPECT_EQ(stats.value_evaluations,
              std::uint64_t(grid.cells[0] + 1) * (grid.cells[1] + 1) * (grid.cells[2] + 1));
    // Linear placement is not on f = 0, but within a cell of it.
    EXPECT_LT(max_distance(*s, mesh), grid.cell);
  }
}

/// True when x is one of the lattice planes of `axis`.
bool on_lattice_plane(const McGrid& grid, int axis, double x) {
  const std::vector<double>& planes = grid.planes[static_cast<std::size_t>(axis)];
  return std::binary_search(planes.begin(), planes.end(), x);
}

TEST(MarchingCubes, VerticesLieOnGridEdges) {
  const SurfacePtr s = test::torus();
  Settings settings;
  settings.grid = 24;
  const Mesh mesh = marching_cubes(*s, settings);
  const McGrid grid = marching_cubes_grid(s->box(), settings);
  for (const Vec3& p : mesh.positions) {
    int on_lattice = 0;
    for (int a = 0; a < 3; ++a) on_lattice += on_lattice_plane(grid, a, p[a]) ? 1 : 0;
    EXPECT_GE(on_lattice, 2) << p.transpose();
  }
}

TEST(MarchingCubes, SphereThroughLatticePointsStaysValid) {
  // Radius 0.5 in [-1, 1]^3: with grid 4, 8 and 16 the points (+-0.5, 0, 0), ... are lattice points
  // when the grid is not offset, and f is exactly 0 there.
  const SurfacePtr s = test::sphere(0.5, Vec3::Zero(), 1.0);
  for (double offset : {1e-3, 0.0})
    for (int n : {4, 8, 16}) {
      Settings settings;
      settings.grid = n;
      settings.grid_offset = offset;
      const Mesh mesh = marching_cubes(*s, settings);
      expect_closed_outward(mesh, 0, "grid " + std::to_string(n) + " offset " + std::to_string(offset));
      EXPECT_LE(max_distance(*s, mesh), 1e-12);
    }
}

TEST(MarchingCubes, OffsetZeroPutsVerticesOnZeroLatticePoints) {
  const SurfacePtr s = test::sphere(0.5, Vec3::Zero(), 1.0);
  Settings settings;
  settings.grid = 4;
  settings.grid_offset = 0.0;
  const Mesh mesh = marching_cubes(*s, settings);
  // Only the centre is negative; its six neighbours are on the sphere: an octahedron.
  EXPECT_EQ(mesh.vertex_count(), 6u);
  EXPECT_EQ(mesh.triangle_count(), 8u);
  for (const Vec3& p : mesh.positions) EXPECT_EQ(p.norm(), 0.5);
}

TEST(MarchingCubes, ClippedSurfaceHasBoundaryOnlyOnTheGridFaces) {
  const SurfacePtr s = test::sphere();
  Settings settings;
  settings.box = Box{Vec3::Zero(), Vec3::Constant(2.0)};
  settings.grid = 20;
  const Mesh mesh = marching_cubes(*s, settings);
  const McGrid grid = marching_cubes_grid(*settings.box, settings);
  const TopologyReport r = analyze_topology(mesh);
  EXPECT_GT(r.boundary_edges, 0u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.consistently_oriented());
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.components[0].boundary_loops, 1u);
  EXPECT_EQ(r.components[0].genus, 0);  // an eighth of a sphere is a disk

  // Every boundary edge lies in one outer plane of the grid: a box face.
  auto on_plane = [&](const Vec3& p, int axis) {
    const std::vector<double>& planes = grid.planes[static_cast<std::size_t>(axis)];
    return p[axis] == planes.front() || p[axis] == planes.back();
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::size_t boundary = 0;
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    ++boundary;
    const Vec3& a = mesh.positions[edge.first];
    const Vec3& b = mesh.positions[edge.second];
    bool shared_plane = false;
    for (int axis = 0; axis < 3; ++axis) shared_plane |= on_plane(a, axis) && on_plane(b, axis);
    EXPECT_TRUE(shared_plane) << a.transpose() << " - " << b.transpose();
  }
  EXPECT_EQ(boundary, r.boundary_edges);
}

TEST(MarchingCubes, GridFitsTheBox) {
  const Box box{Vec3(-1, -2, 0), Vec3(3, 1, 0.5)};
  for (double offset : {0.0, 1e-3, 0.5, 0.999})
    for (int n : {1, 7, 64}) {
      SCOPED_TRACE("offset " + std::to_string(offset) + " grid " + std::to_string(n));
      Settings settings;
      settings.grid = n;
      settings.grid_offset = offset;
      const McGrid g = marching_cubes_grid(box, settings);
      EXPECT_DOUBLE_EQ(g.cell, 4.0 / n);
      EXPECT_EQ(g.cells[0], n);  // the longest axis
      for (std::size_t a = 0; a < 3; ++a) {
        const std::vector<double>& planes = g.planes[a];
        ASSERT_EQ(planes.size(), static_cast<std::size_t>(g.cells[a]) + 1);
        ASSERT_GE(planes.size(), 2u);
        EXPECT_EQ(planes.front(), box.lo[a]);  // the outer planes are the box faces
        EXPECT_EQ(planes.back(), box.hi[a]);
        for (std::size_t i = 1; i + 2 < planes.size(); ++i)
          EXPECT_NEAR(planes[i + 1] - planes[i], g.cell, 1e-12);  // inner cells are cubes
        if (planes.size() > 2) {  // the outer layers: between half a cell and one and a half
          for (const double layer : {planes[1] - planes[0], planes.back() - planes[planes.size() - 2]}) {
            EXPECT_GE(layer, 0.5 * g.cell - 1e-12);
            EXPECT_LT(layer, 1.5 * g.cell + 1e-12);
          }
        } else {
          EXPECT_LT(box.hi[a] - box.lo[a], 1.5 * g.cell + 1e-12);
        }
        if (offset == 0.0) {
          for (std::size_t i = 0; i + 1 < planes.size(); ++i) {
            EXPECT_EQ(planes[i], box.lo[a] + g.cell * static_cast<double>(i));
          }
        }
      }
    }
}

TEST(MarchingCubes, OffsetMovesTheInnerPlanesOffDyadicPoints) {
  // [-1, 1]^3 at grid 8: without offset the inner planes are the dyadic -0.75, ..., 0.75 (0 among
  // them); with the default offset none of them is 0 and they are shifted by different amounts per axis.
  const Box box{Vec3::Constant(-1), Vec3::Constant(1)};
  Settings settings;
  settings.grid = 8;
  const McGrid g = marching_cubes_grid(box, settings);
  for (std::size_t a = 0; a < 3; ++a) {
    EXPECT_EQ(g.cells[a], 8);
    for (std::size_t i = 1; i < 8; ++i) EXPECT_NE(g.planes[a][i], -1.0 + 0.25 * static_cast<double>(i));
    EXPECT_FALSE(std::binary_search(g.planes[a].begin(), g.planes[a].end(), 0.0));
  }
  EXPECT_NE(g.planes[0][1] - (-0.75), g.planes[1][1] - (-0.75));
}

/// Every vertex in the closed box (no tolerance: the grid's outer planes are the faces).
void expect_inside(const Mesh& mesh, const Box& box) {
  ASSERT_GT(mesh.vertex_count(), 0u);
  for (const Vec3& p : mesh.positions)
    ASSERT_TRUE((p.array() >= box.lo.array()).all() && (p.array() <= box.hi.array()).all())
        << p.transpose() << " outside " << format_box(box);
}

TEST(MarchingCubes, VerticesOfClippedSurfacesLieInTheBox) {
  // Open surfaces cut by the box: the gyroid (catalogue box), the plane x = 0.1 and a sphere cut by a
  // box that is not a cube, with and without offset, both edge placements.
  const SurfacePtr gyroid = catalogue_surface("gyroid");
  const SurfacePtr plane = resolve_surface("x - 0.1", Box{Vec3::Constant(-1), Vec3::Constant(1)});
  const SurfacePtr sphere = test::sphere();
  const Box slab{Vec3(-0.7, -0.3, -0.9), Vec3(0.8, 0.35, 0.2)};
  for (double offset : {1e-3, 0.0, 0.7})
    for (EdgeRoot root : {EdgeRoot::Bracketed, EdgeRoot::Linear}) {
      SCOPED_TRACE("offset " + std::to_string(offset));
      Settings settings;
      settings.grid = 20;
      settings.grid_offset = offset;
      settings.edge_root = root;
      expect_inside(marching_cubes(*gyroid, settings), gyroid->box());
      expect_inside(marching_cubes(*plane, settings), plane->box());
      settings.box = slab;
      expect_inside(marching_cubes(*sphere, settings), slab);
    }
}

TEST(MarchingCubes, EvaluatesOnlyInTheBox) {
  // sqrt(x + 1) is NaN for x < -1, just outside the box; the surface is the plane x = -0.75.
  const Box box{Vec3::Constant(-1), Vec3::Constant(1)};
  const SurfacePtr s = resolve_surface("sqrt(x+1)-0.5", box);
  for (double offset : {1e-3, 0.999}) {
    Settings settings;
    settings.grid = 16;
    settings.grid_offset = offset;
    const Mesh mesh = marching_cubes(*s, settings);
    expect_inside(mesh, box);
    for (const Vec3& p : mesh.positions) EXPECT_NEAR(p.x(), -0.75, 1e-12);
    const TopologyReport r = analyze_topology(mesh);
    EXPECT_TRUE(r.manifold());
    EXPECT_EQ(r.components.size(), 1u);
  }
  // A callable that is NaN outside the box on every side; f > 0 near the centre, < 0 at the corners.
  const SurfacePtr guarded = make_surface(
      [](auto x, auto y, auto z) {
        using std::sqrt;
        return sqrt(1.0 - x) + sqrt(1.0 + x) + sqrt(1.0 - y) + sqrt(1.0 + y) + sqrt(1.0 - z) + sqrt(1.0 + z) -
               5.5;
      },
      box);
  Settings settings;
  settings.grid = 12;
  expect_inside(marching_cubes(*guarded, settings), box);
}

TEST(MarchingCubes, BadSettingsAreInputErrors) {
  const SurfacePtr s = test::sphere();
  Settings settings;
  for (int n : {0, -3, 4097}) {
    settings.grid = n;
    EXPECT_THROW(marching_cubes(*s, settings), InputError) << n;
  }
  settings.grid = 8;
  settings.grid_offset = -0.1;
  EXPECT_THROW(marching_cubes(*s, settings), InputError);
  settings.grid_offset = std::nan("");
  EXPECT_THROW(marching_cubes(*s, settings), InputError);
  settings.grid_offset = 0.0;
  settings.box = Box{Vec3::Constant(1), Vec3(2, 0, 2)};
  EXPECT_THROW(marching_cubes(*s, settings), InputError);
}

TEST(MarchingCubes, NaNIsAnEvaluationError) {
  const SurfacePtr s = make_surface(
      [](auto x, auto y, auto z) {
        using std::sqrt;
        return sqrt(x) + y * y + z * z - 1.0;  // NaN for x < 0
      },
      Box{Vec3::Constant(-1), Vec3::Constant(1)});
  Settings settings;
  settings.grid = 8;
  try {
    marching_cubes(*s, settings);
    FAIL() << "no error";
  } catch (const EvaluationError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("f is NaN at (", 0), 0u) << e.what();
  }
}

TEST(MarchingCubes, NoCrossingIsANoSurfaceError) {
  const SurfacePtr s = test::sphere();
  Settings settings;
  settings.grid = 8;
  settings.box = Box{Vec3::Constant(2), Vec3::Constant(3)};
  EXPECT_THROW(marching_cubes(*s, settings), NoSurfaceError);
  settings.box = Box{Vec3::Constant(-0.3), Vec3::Constant(0.3)};  // all inside
  EXPECT_THROW(marching_cubes(*s, settings), NoSurfaceError);
}

TEST(MarchingCubes, CancelAndProgress) {
  const SurfacePtr s = test::torus();
  std::atomic<bool> cancel{true};
  Settings settings;
  settings.grid = 16;
  settings.cancel = &cancel;
  try {
    marching_cubes(*s, settings);
    FAIL() << "no error";
  } catch (const LimitError& e) {
    EXPECT_STREQ(e.what(), "cancelled");
  }

  // Cancelled from the progress callback after the third slab.
  cancel = false;
  std::size_t calls = 0;
  settings.progress = [&](const Progress& p) {
    ++calls;
    EXPECT_EQ(p.done, calls);
    if (p.done == 3) cancel = true;
  };
  EXPECT_THROW(marching_cubes(*s, settings), LimitError);
  EXPECT_EQ(calls, 3u);

  // Uncancelled: one call per slab, the last one complete.
  cancel = false;
  calls = 0;
  Progress last;
  settings.progress = [&](const Progress& p) {
    ++calls;
    last = p;
  };
  marching_cubes(*s, settings);
  const McGrid grid = marching_cubes_grid(s->box(), settings);
  EXPECT_EQ(calls, static_cast<std::size_t>(grid.cells[2]));
  EXPECT_EQ(last.done, last.total);
}

TEST(MarchingCubes, MaxVerticesIsALimitError) {
  const SurfacePtr s = test::sphere();
  Settings settings;
  settings.grid = 16;
  const std::size_t vertices = marching_cubes(*s, settings).vertex_count();
  settings.max_vertices = vertices;
  EXPECT_EQ(marching_cubes(*s, settings).vertex_count(), vertices);
  settings.max_vertices = vertices - 1;
  EXPECT_THROW(marching_cubes(*s, settings), LimitError);
}

}  // namespace
}  // namespace isopatch
