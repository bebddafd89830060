// A tile's base refined with its cut held on its faces' curves, and the tiles put together (tiles.hpp).
#include <isopatch/error.hpp>
#include <isopatch/tiles.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>

#include "api/multiresolution.hpp"
#include "api/task_arena_run.hpp"
#include "blocks/mesh_cut.hpp"
#include "refine/base_edges.hpp"
#include "refine/lattice_layout.hpp"
#include "refine/lattice_relaxation.hpp"
#include "refine/refine_mesh.hpp"

namespace isopatch {
namespace {

using PointKey = std::array<std::uint64_t, 3>;

PointKey key(const Vec3& p) {
  return {std::bit_cast<std::uint64_t>(p.x()), std::bit_cast<std::uint64_t>(p.y()),
          std::bit_cast<std::uint64_t>(p.z())};
}

}  // namespace

TileMesh refine_tile(const Surface& surface, const Settings& settings, const TileGrid& grid,
                     const std::array<int, 3>& tile, const Mesh& base, int level) {
  if (level < 1 || level > 32) throw InputError("the level must be in 1..32", "level");
  TileMesh out;
  out.tile = grid.tile_number(tile);
  if (base.triangles.empty()) {
    out.kept = true;
    out.smallest_angle = 180.0;
    return out;
  }
  const Box box = grid.tile_box(tile);
  refine::RefineParams params = refine_params(settings, box, level);
  params.max_vertices = 0;  // the whole output's budget is the caller's
  params.scale = std::max(grid.domain.diagonal(), 1e-300);
  params.seam = [](std::uint32_t, std::uint32_t) { return true; };  // asked of boundary edges only
  params.seams_on_planes = true;
  refine::RefineResult refined =
      run_in_task_arena(settings, nullptr, [&] { return refine::refine_mesh(base, surface, params); });
  out.failed_points = refined.failed_points;
  if (refined.failed_points > 0) return out;
  out.smallest_angle = refined.smallest_angle;
  // Kept as one process keeps a level, or when the refinement keeps the base's own smallest angle: a
  // sliver the base has where a plane nearly touches the surface is no reason to halve every tile's level.
  out.kept = refinement_kept(settings, refined.smallest_angle) ||
             refined.smallest_angle >= refine::smallest_angle_degrees(base) - kBaseAngleSlack;
  // The band: the output vertices of base triangles with a corner on the cut.
  const std::vector<std::uint8_t> cut = blocks::cut_vertices(base);
  std::vector<std::uint8_t> band(refined.mesh.vertex_count(), 0);
  const auto kk = static_cast<std::size_t>(level * level);
  for (std::size_t t = 0; t < base.triangle_count(); ++t) {
    const Triangle& tri = base.triangles[t];
    if (!cut[tri[0]] && !cut[tri[1]] && !cut[tri[2]]) continue;
    for (std::size_t i = 0; i < kk; ++i)
      for (const std::uint32_t v : refined.mesh.triangles[t * kk + i]) band[v] = 1;
  }
  out.seam_band_vertices = static_cast<std::size_t>(std::count(band.begin(), band.end(), std::uint8_t{1}));
  out.mesh = std::move(refined.mesh);
  out.mesh.attributes.clear();
  out.cut = blocks::cut_vertices(out.mesh);
  return out;
}

Mesh assemble_tiles(const TileGrid& grid, std::span<const TileMesh> tiles) {
  const auto count = static_cast<std::size_t>(grid.tile_count());
  std::vector<const TileMesh*> by_number(count, nullptr);
  for (const TileMesh& tile : tiles) {
    const std::string name = "tile " + std::to_string(tile.tile);
    if (tile.tile < 0 || static_cast<std::size_t>(tile.tile) >= count)
      throw InputError(name + " is not a tile of the grid", "tile");
    if (by_number[static_cast<std::size_t>(tile.tile)]) throw InputError(name + " is given twice", "tile");
    if (tile.failed_points > 0) throw InputError(name + " failed the refinement's guard", "tile");
    by_number[static_cast<std::size_t>(tile.tile)] = &tile;
  }
  for (std::size_t t = 0; t < count; ++t)
    if (!by_number[t]) throw InputError("tile " + std::to_string(t) + " is missing", "tile");

  Mesh mesh;
  std::map<PointKey, std::uint32_t> shared;  // a boundary vertex of an earlier tile -> its number
  for (const TileMesh* tile : by_number) {
    const Mesh& m = tile->mesh;
    const std::vector<std::uint8_t>& boundary = tile->cut;
    if (boundary.size() != m.vertex_count())
      throw InputError("tile " + std::to_string(tile->tile) + " has no cut flag per vertex", "tile");
    std::vector<std::uint32_t> number(m.vertex_count());
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      if (boundary[v]) {
        const auto found = shared.find(key(m.positions[v]));
        if (found != shared.end()) {
          number[v] = found->second;
          continue;
        }
      }
      if (mesh.positions.size() >= std::numeric_limits<std::uint32_t>::max() - 1)
        throw LimitError("the tiles have more vertices than one mesh numbers with 32 bits: write them apart",
                         "tiles");
      number[v] = static_cast<std::uint32_t>(mesh.positions.size());
      mesh.positions.push_back(m.positions[v]);
      if (boundary[v]) shared.emplace(key(m.positions[v]), number[v]);
    }
    for (const Triangle& t : m.triangles)
      mesh.triangles.push_back({number[t[0]], number[t[1]], number[t[2]]});
  }
  // Every boundary edge left must lie on the domain's box: one on an inner plane lost its tile across.
  const auto half = blocks::directed_edges(mesh);
  const auto on_domain = [&](const Vec3& p) {
    return (p.array() == grid.domain.lo.array()).any() || (p.array() == grid.domain.hi.array()).any();
  };
  for (const Triangle& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = t[static_cast<std::size_t>(c)], b = t[static_cast<std::size_t>((c + 1) % 3)];
      if (half.count(blocks::edge_key(b, a))) continue;
      if (!on_domain(mesh.positions[a]) || !on_domain(mesh.positions[b]))
        throw InputError("a tile's seam has no match across its face (tiles made from other face curves?)",
                         "tile");
    }
  return mesh;
}

}  // namespace isopatch
