// The library is deterministic: mesh_surface called twice with the same Settings, on the same surface
// object and on a freshly made one, and with 1, 2 and 4 threads, gives bit-identical positions, the
// same triangles and attributes, and the same statistics (apart from the times and the thread count).
#include <isopatch/catalogue.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace isopatch {
namespace {

struct LibraryCase {
  const char* name;  ///< the test name: letters, digits and '_'
  const char* surface;
  Settings (*settings)();
};

Settings projection(double edge_length) {
  Settings s;
  s.edge_length = edge_length;
  return s;
}

const LibraryCase kCases[] = {
    {"torus_projection", "torus", [] { return projection(0.1); }},  // the default method, whole clean-up
    {"blobby_projection", "blobby", [] { return projection(0.08); }},
    {"genus2_remesh0", "genus2",
     [] {
       Settings s = projection(0.05);
       s.remesh_iterations = 0;
       return s;
     }},
    {"genus2_coons", "genus2",
     [] {
       Settings s = projection(0.05);
       s.base = Settings::Base::Coons;
       s.vertex_roles = true;  // an attribute, compared too
       return s;
     }},
    {"blobby_max_error", "blobby",
     [] {
       Settings s;
       s.max_error = 3e-3;
       return s;
     }},
    {"tanglecube_size_field", "tanglecube",
     [] {
       Settings s;
       s.size_field = [](const Vec3& p) { return 0.3 + 0.06 * p.x(); };
       return s;
     }},
    {"tanglecube_preview", "tanglecube",
     [] {
       Settings s;
       s.quality = Quality::Preview;
       s.vertex_roles = true;
       return s;
     }},
    {"torus_fine", "torus",
     [] {
       Settings s = projection(0.15);
       s.quality = Quality::Fine;
       return s;
     }},
    {"torus_mc", "torus",
     [] {
       Settings s;
       s.method = Method::MarchingCubes;
       s.grid = 48;
       return s;
     }},
};

void PrintTo(const LibraryCase& c, std::ostream* out) {
  *out << c.name;
}

/// Index of the first vertex whose coordinates differ in any bit, or the vertex count.
std::size_t first_different_position(const Mesh& a, const Mesh& b) {
  for (std::size_t v = 0; v < a.positions.size(); ++v)
    for (int i = 0; i < 3; ++i)
      if (std::bit_cast<std::uint64_t>(a.positions[v][i]) != std::bit_cast<std::uint64_t>(b.positions[v][i]))
        return v;
  return a.positions.size();
}

void expect_identical(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  const std::size_t v = first_different_position(a, b);
  EXPECT_EQ(v, a.vertex_count()) << "positions differ first at vertex " << v;
  EXPECT_TRUE(a.triangles == b.triangles);
  ASSERT_EQ(a.attributes.size(), b.attributes.size());
  for (std::size_t i = 0; i < a.attributes.size(); ++i) {
    EXPECT_EQ(a.attributes[i].name, b.attributes[i].name);
    EXPECT_TRUE(a.attributes[i].values == b.attributes[i].values) << a.attributes[i].name;
  }
}

void expect_same_counts(const MeshStats& a, const MeshStats& b) {
  EXPECT_EQ(a.value_evaluations, b.value_evaluations);
  EXPECT_EQ(a.gradient_evaluations, b.gradient_evaluations);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
  // Every statistic but the time.
  const auto named = [](const MeshStats& s) {
    std::vector<std::tuple<std::string, std::string, double>> out;
    visit_stats(s, [&out](std::string_view stage, std::string_view name, double value) {
      if (name != "seconds" && stage != "seconds" && name != "threads") out.emplace_back(stage, name, value);
    });
    return out;
  };
  EXPECT_EQ(named(a), named(b));
}

class LibraryDeterminism : public ::testing::TestWithParam<LibraryCase> {};

TEST_P(LibraryDeterminism, TwoCallsGiveTheSameMesh) {
  const LibraryCase& c = GetParam();
  const Settings settings = c.settings();
  const SurfacePtr surface = catalogue_surface(c.surface);
  MeshStats stats[3];
  const Mesh first = mesh_surface(*surface, settings, &stats[0]);
  const Mesh again = mesh_surface(*surface, settings, &stats[1]);
  const Mesh fresh = mesh_surface(*catalogue_surface(c.surface), settings, &stats[2]);
  ASSERT_GT(first.vertex_count(), 100u);
  ASSERT_GT(first.triangle_count(), 200u);
  {
    SCOPED_TRACE("the same surface object again");
    expect_identical(first, again);
    expect_same_counts(stats[0], stats[1]);
  }
  {
    SCOPED_TRACE("a freshly made surface");
    expect_identical(first, fresh);
    expect_same_counts(stats[0], stats[2]);
  }
}

TEST_P(LibraryDeterminism, AnyThreadCountGivesTheSameMesh) {
  const LibraryCase& c = GetParam();
  const SurfacePtr surface = catalogue_surface(c.surface);
  Settings settings = c.settings();
  MeshStats stats[3];
  Mesh meshes[3];
  constexpr int kThreads[] = {1, 2, 4};
  for (int i = 0; i < 3; ++i) {
    settings.threads = kThreads[i];
    meshes[i] = mesh_surface(*surface, settings, &stats[i]);
    EXPECT_EQ(stats[i].threads, kThreads[i]);
  }
  ASSERT_GT(meshes[0].vertex_count(), 100u);
  for (int i = 1; i < 3; ++i) {
    SCOPED_TRACE("1 thread against " + std::to_string(kThreads[i]));
    expect_identical(meshes[0], meshes[i]);
    expect_same_counts(stats[0], stats[i]);
  }
}

INSTANTIATE_TEST_SUITE_P(Configurations, LibraryDeterminism, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<LibraryCase>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace isopatch
