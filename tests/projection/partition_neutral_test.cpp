// The mesher knows partitions only through cell_partition.hpp: a partitioner that numbers its cells and
// faces differently (here the octree's, reversed) gives the same mesh, up to the order of vertices.
#include <isopatch/resolve_surface.hpp>
#include <isopatch/settings.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "partition/octree_partitioner.hpp"
#include "projection/refining_mesher.hpp"
#include "surface/target_size.hpp"

namespace isopatch {
namespace {

/// The octree with its cells and faces in reverse order.
class ReversedOctree final : public Partitioner {
 public:
  ReversedOctree(const Surface& surface, const Box& box, const PartitionSettings& settings)
      : octree_(surface, box, settings) {}

  CellPartition build() override {
    CellPartition p = octree_.build();
    const auto faces = static_cast<std::uint32_t>(p.faces.size());
    std::reverse(p.faces.begin(), p.faces.end());
    std::reverse(p.cells.begin(), p.cells.end());
    cells_ = p.cells.size();
    const auto cells = static_cast<std::uint32_t>(cells_);
    for (CellFace& face : p.faces) {
      for (std::uint32_t& c : face.cells)
        if (c != kNoCell) c = cells - 1 - c;
      std::sort(face.cells.begin(), face.cells.end());
    }
    for (PartitionCell& cell : p.cells)
      for (CellLoop& loop : cell.loops)
        for (std::uint32_t& f : loop.side_faces) f = faces - 1 - f;
    return p;
  }
  bool start_finer() override { return octree_.start_finer(); }
  void split(std::span<const std::size_t> cells) override {
    std::vector<std::size_t> original;
    for (const std::size_t c : cells) original.push_back(cells_ - 1 - c);
    octree_.split(original);
  }
  int max_level() const override { return octree_.max_level(); }
  bool only_grazes_ambiguous_faces(std::size_t cell, const Sampler& f) const override {
    return octree_.only_grazes_ambiguous_faces(cells_ - 1 - cell, f);
  }

 private:
  OctreePartitioner octree_;
  std::size_t cells_ = 0;
};

std::vector<std::array<double, 3>> sorted_positions(const Mesh& mesh) {
  std::vector<std::array<double, 3>> p;
  for (const Vec3& v : mesh.positions) p.push_back({v.x(), v.y(), v.z()});
  std::sort(p.begin(), p.end());
  return p;
}

TEST(PartitionNeutrality, ANumberingOfItsOwnGivesTheSameMesh) {
  for (const char* name : {"torus", "genus2"}) {
    const SurfacePtr surface = catalogue_surface(name);
    Settings settings;
    settings.edge_length = surface->box().size().maxCoeff() / 40.0;
    const Box box = surface->box();
    PartitionSettings octree;
    octree.surface_depth = 3;
    octree.max_depth = 7;
    const CellMesherSettings stages{settings, settings, settings};
    const TargetSizes sizes = target_sizes(settings, box);
    OctreePartitioner plain(*surface, box, octree);
    ReversedOctree reversed(*surface, box, octree);
    MeshStats a, b;
    const Mesh ma = mesh_refining(*surface, plain, settings, stages, sizes, &a);
    const Mesh mb = mesh_refining(*surface, reversed, settings, stages, sizes, &b);
    ASSERT_GT(ma.vertex_count(), 500u) << name;
    EXPECT_EQ(ma.triangle_count(), mb.triangle_count()) << name;
    EXPECT_EQ(sorted_positions(ma), sorted_positions(mb)) << name;
    EXPECT_EQ(a.projection.value().refinements, b.projection.value().refinements) << name;
    EXPECT_EQ(a.projection->patches_by_sides, b.projection->patches_by_sides) << name;
  }
}

}  // namespace
}  // namespace isopatch
