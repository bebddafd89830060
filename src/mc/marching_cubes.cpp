// The marching cubes mesher (Lorensen & Cline 1987) over one z-slab of cells at a time.
//
// Watertightness rests on two facts: each grid edge gets exactly one vertex, created the first time
// the edge is seen and found again by its lattice position, and the generated table (table.cpp)
// makes neighbouring cubes agree on every shared face. Vertices of the x- and y-edges of a lattice
// layer are kept while the two slabs on either side of the layer are processed; z-edges belong to a
// single slab. Values are compared with the same rule everywhere (f < 0 negative, f >= 0 positive).
#include "core/cube_numbering.hpp"
#include "mc/edge_root.hpp"

#include <isopatch/error.hpp>
#include <isopatch/marching_cubes.hpp>

#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace isopatch {
namespace {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

// Where cube edge e lies in the lattice: the edge along `axis` leaving the cube corner at offset `lower`.
struct LatticeEdge {
  int axis;
  std::array<int, 3> lower;
};

constexpr std::array<LatticeEdge, 12> kLatticeEdge = [] {
  std::array<LatticeEdge, 12> table{};
  for (int e = 0; e < 12; ++e) table[e] = {cube::edge_axis(e), cube::kCorner[cube::edge_lower_corner(e)]};
  return table;
}();

class SlabMesher {
 public:
  SlabMesher(const Surface& surface, const MarchingCubesSettings& settings, const BudgetSettings& budget,
             const McGrid& grid)
      : surface_(surface),
        settings_(settings),
        budget_(budget),
        grid_(grid),
        nx_(grid.cells[0]),
        ny_(grid.cells[1]),
        nz_(grid.cells[2]),
        layer_points_(static_cast<std::size_t>(nx_ + 1) * (ny_ + 1)) {
    for (int s = 0; s < 2; ++s) {
      values_[s].resize(layer_points_);
      x_vertex_[s].resize(static_cast<std::size_t>(nx_) * (ny_ + 1));
      y_vertex_[s].resize(static_cast<std::size_t>(nx_ + 1) * ny_);
    }
    z_vertex_.resize(layer_points_);
    points_.resize(layer_points_);
  }

  Mesh run() {
    sample_layer(0, 0);
    layer_vertices(0, 0);
    for (int k = 0; k < nz_; ++k) {
      budget_.check_cancel();
      const int below = k & 1;
      const int above = below ^ 1;
      sample_layer(k + 1, above);
      layer_vertices(k + 1, above);
      z_vertices(k, below, above);
      emit_cells(below, above);
      if (budget_.progress)
        budget_.progress(Progress{static_cast<std::size_t>(k) + 1, static_cast<std::size_t>(nz_)});
    }
    return std::move(mesh_);
  }

  std::uint64_t evaluations() const { return evaluations_; }

 private:
  Vec3 point(int i, int j, int k) const { return grid_.point(i, j, k); }
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * (nx_ + 1) + i; }

  void sample_layer(int k, int slot) {
    for (int j = 0; j <= ny_; ++j)
      for (int i = 0; i <= nx_; ++i) points_[at(i, j)] = point(i, j, k);
    surface_.values(points_, values_[slot]);
    evaluations_ += layer_points_;
    for (std::size_t p = 0; p < layer_points_; ++p) mc::check_value(values_[slot][p], points_[p]);
  }

  // The vertex on the edge from lattice point a (value fa) to b (value fb), or kNoVertex.
  std::uint32_t edge_vertex(const Vec3& a, const Vec3& b, double fa, double fb) {
    if ((fa < 0.0) == (fb < 0.0)) return kNoVertex;
    if (budget_.max_vertices != 0 && mesh_.positions.size() >= budget_.max_vertices)
      throw LimitError("the mesh would exceed the vertex budget of " + std::to_string(budget_.max_vertices),
                       "max_vertices");
    if (mesh_.positions.size() >= kNoVertex) throw LimitError("marching cubes: more than 2^32 - 1 vertices");
    mesh_.positions.push_back(mc::edge_root(surface_, a, b, fa, fb, settings_.edge_root, evaluations_));
    return static_cast<std::uint32_t>(mesh_.positions.size() - 1);
  }

  void layer_vertices(int k, int slot) {
    const std::vector<double>& f = values_[slot];
    for (int j = 0; j <= ny_; ++j)
      for (int i = 0; i < nx_; ++i)
        x_vertex_[slot][x_edge(i, j)] =
            edge_vertex(point(i, j, k), point(i + 1, j, k), f[at(i, j)], f[at(i + 1, j)]);
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i <= nx_; ++i)
        y_vertex_[slot][y_edge(i, j)] =
            edge_vertex(point(i, j, k), point(i, j + 1, k), f[at(i, j)], f[at(i, j + 1)]);
  }

  void z_vertices(int k, int below, int above) {
    for (int j = 0; j <= ny_; ++j)
      for (int i = 0; i <= nx_; ++i)
        z_vertex_[at(i, j)] = edge_vertex(point(i, j, k), point(i, j, k + 1), values_[below][at(i, j)],
                                          values_[above][at(i, j)]);
  }

  std::size_t x_edge(int i, int j) const { return static_cast<std::size_t>(j) * nx_ + i; }
  std::size_t y_edge(int i, int j) const { return static_cast<std::size_t>(j) * (nx_ + 1) + i; }

  void emit_cells(int below, int above) {
    const std::array<McCase, 256>& table = marching_cubes_table();
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) {
        int case_index = 0;
        for (int c = 0; c < 8; ++c) {
          const auto& corner = cube::kCorner[c];
          const double f = values_[corner[2] != 0 ? above : below][at(i + corner[0], j + corner[1])];
          if (f < 0.0) case_index |= 1 << c;
        }
        if (case_index == 0 || case_index == 255) continue;
        std::array<std::uint32_t, 12> vertex{};  // by cube edge (core/cube_numbering.hpp)
        for (int e = 0; e < 12; ++e) {
          const auto& [axis, lower] = kLatticeEdge[e];
          const int layer = lower[2] != 0 ? above : below;
          vertex[e] = axis == 0   ? x_vertex_[layer][x_edge(i + lower[0], j + lower[1])]
                      : axis == 1 ? y_vertex_[layer][y_edge(i + lower[0], j + lower[1])]
                                  : z_vertex_[at(i + lower[0], j + lower[1])];
        }
        for (const std::array<int, 3>& t : table[case_index].triangles)
          mesh_.triangles.push_back({vertex[t[0]], vertex[t[1]], vertex[t[2]]});
      }
  }

  const Surface& surface_;
  const MarchingCubesSettings& settings_;
  const BudgetSettings& budget_;
  McGrid grid_;
  int nx_, ny_, nz_;
  std::size_t layer_points_;
  std::vector<Vec3> points_;                            // lattice points of the layer being sampled
  std::array<std::vector<double>, 2> values_;           // f on the layers below and above the slab
  std::array<std::vector<std::uint32_t>, 2> x_vertex_;  // vertices on x-edges of those layers
  std::array<std::vector<std::uint32_t>, 2> y_vertex_;  // vertices on y-edges of those layers
  std::vector<std::uint32_t> z_vertex_;                 // vertices on z-edges of the current slab
  Mesh mesh_;
  std::uint64_t evaluations_ = 0;
};

}  // namespace

Mesh marching_cubes(const Surface& surface, const Settings& settings, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  settings.BudgetSettings::validate();
  const Box box = settings.box.value_or(surface.box());
  const McGrid grid = marching_cubes_grid(box, settings);  // checks the box and the grid settings
  SlabMesher mesher(surface, settings, settings, grid);
  Mesh mesh = mesher.run();
  if (mesh.triangles.empty())
    throw NoSurfaceError("no surface in the box " + format_box(box) + ": f does not change sign on the " +
                         std::to_string(grid.cells[0]) + "x" + std::to_string(grid.cells[1]) + "x" +
                         std::to_string(grid.cells[2]) + " grid");
  if (stats != nullptr) {
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->value_evaluations = mesher.evaluations();
    stats->vertices = mesh.vertex_count();
    stats->triangles = mesh.triangle_count();
    stats->marching_cubes = MarchingCubesStats{static_cast<std::uint64_t>(grid.cells[0]) *
                                                   static_cast<std::uint64_t>(grid.cells[1]) *
                                                   static_cast<std::uint64_t>(grid.cells[2]),
                                               grid.cell};
  }
  return mesh;
}

}  // namespace isopatch
