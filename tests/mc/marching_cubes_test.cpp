// The marching cubes mesher on the benchmark surfaces and on the cases that break naive versions:
// lattice points exactly on the surface, clipping by the box, NaN, no surface, limits.
#include "test_surfaces.hpp"

#include <isopatch/error.hpp>
#include <isopatch/marching_cubes.hpp>
#include <isopatch/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <string>
#include <utility>

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

TEST(MarchingCubes, VerticesLieOnGridEdges) {
  const SurfacePtr s = test::torus();
  Settings settings;
  settings.grid = 24;
  const Mesh mesh = marching_cubes(*s, settings);
  const McGrid grid = marching_cubes_grid(s->box(), settings);
  for (const Vec3& p : mesh.positions) {
    int on_lattice = 0;
    for (int a = 0; a < 3; ++a) {
      const double index = std::round((p[a] - grid.origin[a]) / grid.cell);
      EXPECT_GE(index, 0.0);
      EXPECT_LE(index, grid.cells[a]);
      if (p[a] == (grid.origin + grid.cell * Vec3::Constant(index))[a]) ++on_lattice;
    }
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

  // Every boundary edge lies in one outer plane of the grid.
  auto on_plane = [&](const Vec3& p, int axis) {
    return p[axis] == grid.origin[axis] || p[axis] == grid.origin[axis] + grid.cell * grid.cells[axis];
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

TEST(MarchingCubes, GridCoversTheBox) {
  const Box box{Vec3(-1, -2, 0), Vec3(3, 1, 0.5)};
  for (double offset : {0.0, 1e-3, 0.5, 0.999})
    for (int n : {1, 7, 64}) {
      Settings settings;
      settings.grid = n;
      settings.grid_offset = offset;
      const McGrid g = marching_cubes_grid(box, settings);
      EXPECT_DOUBLE_EQ(g.cell, 4.0 / n);
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(g.origin[a], box.lo[a]);
        EXPECT_GT(g.origin[a], box.lo[a] - g.cell);
        EXPECT_GE(g.origin[a] + g.cell * g.cells[a], box.hi[a] - 1e-9 * g.cell);
        EXPECT_LT(g.origin[a] + g.cell * (g.cells[a] - 1), box.hi[a]);  // no cell to spare
      }
      if (offset == 0.0) {
        EXPECT_EQ(g.cells[0], n);
        EXPECT_EQ(g.origin, box.lo);
      }
    }
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
