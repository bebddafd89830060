// OpenVDB grids as surfaces (vdb_surface.hpp): grids made with OpenVDB's own tools in memory, read back
// from their bytes; the spline's values, derivatives and bounds, its memory, meshes of it, refusals.
#include <gtest/gtest.h>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/topology.hpp>
#include <isopatch/vdb_surface.hpp>

#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <unistd.h>
#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "mesh_checks.hpp"

namespace isopatch {
namespace {

constexpr double kVoxel = 0.05;

/// The grids as OpenVDB's file writer saves them (with grid offsets), read back as bytes.
std::string bytes_of(const openvdb::GridPtrVec& grids) {
  openvdb::initialize();
  const std::string path = ::testing::TempDir() + "isopatch_vdb_test_" + std::to_string(::getpid()) + ".vdb";
  openvdb::io::File(path).write(grids);
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  std::string bytes(static_cast<std::size_t>(in.tellg()), '\0');
  in.seekg(0);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  std::remove(path.c_str());
  return bytes;
}

/// The same as OpenVDB's stream writer writes them (no grid offsets).
std::string stream_bytes_of(const openvdb::GridPtrVec& grids) {
  openvdb::initialize();
  std::ostringstream out(std::ios_base::binary);
  openvdb::io::Stream(out).write(grids);
  return out.str();
}

openvdb::FloatGrid::Ptr sphere(float radius, const openvdb::Vec3f& centre,
                               const std::string& name = "sphere") {
  openvdb::initialize();
  auto g = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(radius, centre,
                                                                    static_cast<float>(kVoxel), 3.0f);
  g->setName(name);
  return g;
}

SurfacePtr sphere_surface() {
  return decode_vdb_surface(bytes_of({sphere(1.0f, {0.0f, 0.0f, 0.0f})}));
}

TEST(VdbSurface, FollowsTheSignedDistanceOfALevelSetSphere) {
  const SurfacePtr s = sphere_surface();
  EXPECT_EQ(s->name(), "<memory>:sphere");
  std::mt19937 rng(5);
  std::normal_distribution<double> n;
  // Within 0.4 voxels of the zero set: every sample the spline uses there is stored (band of 3 voxels).
  std::uniform_real_distribution<double> r(1.0 - 0.4 * kVoxel, 1.0 + 0.4 * kVoxel);
  for (int i = 0; i < 200; ++i) {
    Vec3 p(n(rng), n(rng), n(rng));
    p = p.normalized() * r(rng);
    EXPECT_NEAR(s->value(p), p.norm() - 1.0, 2e-5) << p.transpose();
    EXPECT_NEAR(s->value_gradient(p).gradient.norm(), 1.0, 2e-3);
  }
  EXPECT_NEAR(s->value(Vec3(0, 0, 0)), -3 * kVoxel, 1e-7);  // the inside tiles' value (a float): constant
  EXPECT_NEAR(s->value(Vec3(40, 0, 0)), 3 * kVoxel, 1e-7);  // the background
  EXPECT_TRUE(std::isnan(s->value(Vec3(1e300, 0, 0))));
}

TEST(VdbSurface, DerivativesAreThoseOfTheValue) {
  const SurfacePtr s = sphere_surface();
  const double h = 1e-6;
  for (const Vec3& p : {Vec3(0.97, 0.1, 0.05), Vec3(-0.3, 0.62, -0.7), Vec3(0.55, 0.55, 0.61)}) {
    const SecondOrder d = s->second_order(p);
    EXPECT_DOUBLE_EQ(d.value, s->value(p));
    for (int a = 0; a < 3; ++a) {
      const Vec3 e = Vec3::Unit(a) * h;
      EXPECT_NEAR(d.gradient[a], (s->value(p + e) - s->value(p - e)) / (2 * h), 1e-6);
      const Vec3 dg = (s->value_gradient(p + e).gradient - s->value_gradient(p - e).gradient) / (2 * h);
      for (int b = 0; b < 3; ++b) EXPECT_NEAR(d.hessian(a, b), dg[b], 1e-4 * (1 + std::abs(dg[b])));
    }
  }
}

TEST(VdbSurface, BoundsEncloseEveryValueAndGradientInTheirBox) {
  const SurfacePtr s = sphere_surface();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> centre(-1.6, 1.6), size(0.0, 1.0), t(0.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    // Sizes from a fraction of a voxel (scanned coefficient by coefficient) to most of the grid
    // (brick summaries, tiles, background).
    const double side = std::pow(10.0, -2.5 + 3.0 * size(rng));
    const Vec3 c(centre(rng), centre(rng), centre(rng));
    const Box box{c - Vec3::Constant(side / 2), c + Vec3::Constant(side / 2)};
    const auto g = s->gradient_bound(box);
    ASSERT_TRUE(g.has_value());
    for (int k = 0; k < 20; ++k) {
      const Vec3 p = box.lo + (box.hi - box.lo).cwiseProduct(Vec3(t(rng), t(rng), t(rng)));
      const ValueGradient vg = s->value_gradient(p);
      ASSERT_TRUE(g->value.contains(vg.value)) << "box " << c.transpose() << " side " << side;
      for (std::size_t a = 0; a < 3; ++a)
        ASSERT_TRUE(g->gradient[a].contains(vg.gradient[static_cast<int>(a)]))
            << "axis " << a << " side " << side;
    }
  }
  // Away from the band the bounds prove there is no surface: inside and outside, small and large boxes.
  EXPECT_TRUE(s->bound(Box{Vec3::Constant(-0.3), Vec3::Constant(0.3)})->excludes_zero());
  EXPECT_TRUE(s->bound(Box{Vec3(1.3, -2, -2), Vec3(30, 2, 2)})->excludes_zero());
}

TEST(VdbSurface, ReproducesCubicPolynomialsWhereTheyAreStored) {
  openvdb::initialize();
  auto grid = openvdb::DoubleGrid::create(0.0);
  grid->setName("cubic");
  grid->setTransform(openvdb::math::Transform::createLinearTransform(0.5));
  const auto f = [](double x, double y, double z) {
    return 0.1 * x * x * x - 0.3 * x * y * z + 0.2 * z * z - y + 0.5;
  };
  auto accessor = grid->getAccessor();
  for (int i = -16; i < 16; ++i)
    for (int j = -16; j < 16; ++j)
      for (int k = -16; k < 16; ++k) accessor.setValue({i, j, k}, f(0.5 * i, 0.5 * j, 0.5 * k));
  const SurfacePtr s = decode_vdb_surface(bytes_of({grid}));
  for (const Vec3& p : {Vec3(0.3, -1.1, 2.2), Vec3(-3.7, 2.05, 0.0), Vec3(1.0, 1.0, -4.4)})
    EXPECT_NEAR(s->value(p), f(p.x(), p.y(), p.z()), 1e-6) << p.transpose();  // coefficients in floats
}

TEST(VdbSurface, MemoryFollowsTheActiveVoxelsNotTheBoundingBox) {
  std::vector<std::size_t> bytes;
  for (const float gap : {3.0f, 60.0f}) {
    auto a = sphere(0.5f, {0.0f, 0.0f, 0.0f}, "pair");
    auto b = sphere(0.5f, {gap, 0.0f, 0.0f});
    a->tree().combine(b->tree(), [](const float& x, const float& y, float& out) { out = std::min(x, y); });
    const SurfacePtr s = decode_vdb_surface(bytes_of({a}));
    bytes.push_back(vdb_surface_bytes(*s));
    // Under 200 bytes per stored voxel (coefficients around every leaf, in floats).
    EXPECT_LT(static_cast<double>(bytes.back()), 200.0 * static_cast<double>(a->activeVoxelCount()));
  }
  // A 20 times longer box, the same memory (within the leaves' different cut by the grid).
  EXPECT_LT(static_cast<double>(bytes[1]), 1.1 * static_cast<double>(bytes[0]));
  EXPECT_GT(static_cast<double>(bytes[1]), 0.9 * static_cast<double>(bytes[0]));
  EXPECT_EQ(vdb_surface_bytes(*catalogue_surface("sphere")), 0U);
}

TEST(VdbSurface, MeshesASphereOnItsSplineWithGoodTriangles) {
  const SurfacePtr s = sphere_surface();
  Settings settings;
  settings.edge_length = 0.1;
  const Mesh mesh = mesh_surface(*s, settings);
  const TopologyReport topology = analyze_topology(mesh);
  EXPECT_TRUE(topology.watertight() && topology.manifold() && topology.outward_oriented());
  EXPECT_EQ(topology.euler_characteristic, 2);
  for (const Vec3& p : mesh.positions) ASSERT_LT(std::abs(s->value(p)), 1e-9);
  const std::vector<int> valence = test::valences(mesh);
  const auto sixes = std::count(valence.begin(), valence.end(), 6);
  EXPECT_GT(static_cast<double>(sixes), 0.94 * static_cast<double>(valence.size()));
  EXPECT_GT(test::min_angle_degrees(mesh), 25.0);
}

openvdb::FloatGrid::Ptr with_transform(openvdb::math::Transform::Ptr t) {
  auto g = sphere(1.0f, {0.0f, 0.0f, 0.0f});
  g->setTransform(std::move(t));
  return g;
}

TEST(VdbSurface, RefusesWhatItCannotRead) {
  const auto io_error = [](const std::string& bytes, const char* words) {
    try {
      decode_vdb_surface(bytes, {}, "bad.vdb");
      ADD_FAILURE() << "accepted: " << words;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  };
  io_error("", "not an OpenVDB file");
  io_error("ply\nformat ascii 1.0\n", "not an OpenVDB file");
  const std::string good = bytes_of({sphere(1.0f, {0.0f, 0.0f, 0.0f})});
  for (const std::size_t cut : {std::size_t{8}, std::size_t{40}, good.size() / 3, good.size() - 10}) {
    SCOPED_TRACE("cut at " + std::to_string(cut) + " of " + std::to_string(good.size()));
    io_error(good.substr(0, cut), "bad.vdb");
  }
  auto vectors = openvdb::Vec3SGrid::create();
  vectors->tree().setValue({0, 0, 0}, openvdb::Vec3s(1, 2, 3));
  io_error(bytes_of({vectors}), "float or double");
  auto rotated = openvdb::math::Transform::createLinearTransform(kVoxel);
  rotated->preRotate(0.3, openvdb::math::Z_AXIS);
  io_error(bytes_of({with_transform(rotated)}), "axis-aligned");
  auto nan = sphere(1.0f, {0.0f, 0.0f, 0.0f});
  nan->tree().setValue({20, 0, 0}, std::nanf(""));
  io_error(bytes_of({nan}), "non-finite value at voxel (20, 0, 0)");

  EXPECT_THROW(decode_vdb_surface(good, VdbSource{"", 5.0, false}), NoSurfaceError);
  EXPECT_THROW(decode_vdb_surface(good, VdbSource{"", std::nan(""), false}), InputError);
  const std::string two =
      bytes_of({sphere(1.0f, {0.0f, 0.0f, 0.0f}, "a"), sphere(0.5f, {3.0f, 0.0f, 0.0f}, "b")});
  EXPECT_THROW(decode_vdb_surface(two), InputError);
  // A stream of one grid reads as a file does; of two, it is refused (its second grid's place is known
  // only once the first is read).
  EXPECT_EQ(decode_vdb_surface(stream_bytes_of({sphere(1.0f, {0.0f, 0.0f, 0.0f})}))->value(Vec3(1, 0, 0)),
            decode_vdb_surface(good)->value(Vec3(1, 0, 0)));
  io_error(stream_bytes_of({sphere(1.0f, {0.0f, 0.0f, 0.0f}, "a"), sphere(0.5f, {3.0f, 0.0f, 0.0f}, "b")}),
           "written as a stream");
  EXPECT_THROW(decode_vdb_surface(two, VdbSource{"c", 0.0, false}), InputError);
  EXPECT_EQ(decode_vdb_surface(two, VdbSource{"b", 0.0, false})->name(), "<memory>:b");
  EXPECT_THROW(vdb_surface("/nonexistent/model.vdb"), IoError);
  EXPECT_TRUE(is_vdb_path("model.VDB") && !is_vdb_path("model.npy") && !is_vdb_path("vdb"));
}

/// `bytes` with the root node's tile count (entry 0) or child count (entry 1) of its first grid set to
/// `count`: they follow the transform's type name, its five vectors, the buffer count and the
/// background of a float grid.
std::string with_root_count(std::string bytes, int entry, std::uint32_t count) {
  const std::string map = "UniformScaleMap";
  const std::size_t at =
      bytes.find(map) + map.size() + 5 * 3 * sizeof(double) + 4 + sizeof(float) + 4 * entry;
  EXPECT_LT(at + 4, bytes.size());
  std::memcpy(bytes.data() + at, &count, sizeof count);
  return bytes;
}

TEST(VdbSurface, RefusesARootNodeDeclaringMoreEntriesThanItsGridHoldsAtOnce) {
  // OpenVDB reads a root node's entries one by one whatever is left of the stream: a corrupt count of a
  // billion kept it busy for 35 s. The pre-scan refuses it before reading.
  const std::string file = bytes_of({sphere(1.0f, {0.0f, 0.0f, 0.0f})});
  const std::string stream = stream_bytes_of({sphere(1.0f, {0.0f, 0.0f, 0.0f})});
  EXPECT_EQ(with_root_count(file, 1, 8), file);  // where the counts are: the sphere's 8 children
  for (const std::string& good : {file, stream}) {
    for (const int entry : {0, 1}) {
      try {
        decode_vdb_surface(with_root_count(good, entry, 1u << 30), {}, "bad.vdb");
        ADD_FAILURE() << "accepted a count of 2^30 in entry " << entry;
      } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.vdb: the file is corrupt or truncated (its root node"),
                  std::string::npos)
            << e.what();
      }
    }
  }
}

TEST(VdbSurface, ReadsAGridThatSharesAnotherGridsTree) {
  // OpenVDB stores a grid sharing another's tree as an instance, without a tree of its own.
  const auto a = sphere(1.0f, {0.0f, 0.0f, 0.0f}, "a");
  const openvdb::GridBase::Ptr b = a->copyGrid();
  b->setName("b");
  const std::string bytes = bytes_of({a, b});
  EXPECT_EQ(decode_vdb_surface(bytes, VdbSource{"b", 0.0, false})->value(Vec3(0.5, 0.1, 0.0)),
            decode_vdb_surface(bytes, VdbSource{"a", 0.0, false})->value(Vec3(0.5, 0.1, 0.0)));
}

TEST(VdbSurface, InsideAboveTurnsTheSign) {
  const std::string good = bytes_of({sphere(1.0f, {0.0f, 0.0f, 0.0f})});
  const SurfacePtr below = decode_vdb_surface(good);
  const SurfacePtr above = decode_vdb_surface(good, VdbSource{"", 0.0, true});
  const Vec3 p(0.6, 0.7, 0.2);
  EXPECT_DOUBLE_EQ(above->value(p), -below->value(p));
  EXPECT_TRUE((above->value_gradient(p).gradient + below->value_gradient(p).gradient).isZero(0.0));
  const auto b = above->bound(Box{Vec3::Constant(-0.2), Vec3::Constant(0.2)});
  EXPECT_GT(b->lo, 0.0);  // the inside is positive now
}

}  // namespace
}  // namespace isopatch
