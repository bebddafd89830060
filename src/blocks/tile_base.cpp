// A tile's base with its cut made of its faces' curves (tiles.hpp).
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/tiles.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "api/multiresolution.hpp"
#include "blocks/block_piece.hpp"
#include "blocks/mesh_cut.hpp"
#include "blocks/tile_seam.hpp"
#include "remesh/remesh_presets.hpp"

namespace isopatch {
namespace {

void check_tile_input(const Settings& settings, const TileGrid& grid, const std::array<int, 3>& tile,
                      std::span<const FaceCurves> faces, double edge) {
  blocks::check_tiled_settings(settings);
  for (int a = 0; a < 3; ++a)
    if (tile[static_cast<std::size_t>(a)] < 0 ||
        tile[static_cast<std::size_t>(a)] >= grid.counts[static_cast<std::size_t>(a)])
      throw InputError("the tile is not in the grid", "tile");
  const auto expected = tile_faces(tile);
  if (faces.size() != expected.size())
    throw InputError("a tile's base takes the curves of its six faces", "faces");
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (!(faces[f].face == expected[f]) || faces[f].spacing != edge)
      throw InputError("the face curves given are not the tile's faces at this edge length", "faces");
}

/// `mesh` renumbered with its cut's vertices first, in the lexicographic order of their positions: the
/// refinement makes a base edge's points from its lower-numbered end, so the tiles beside a face, which
/// share its cut vertices but not their numbers, then make them from the same end.
Mesh cut_first(const Mesh& mesh) {
  const std::vector<std::uint8_t> cut = blocks::cut_vertices(mesh);
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
    if (cut[v]) order.push_back(v);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 &p = mesh.positions[a], &q = mesh.positions[b];
    return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
  });
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
    if (!cut[v]) order.push_back(v);
  std::vector<std::uint32_t> number(mesh.vertex_count());
  Mesh out;
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    number[order[i]] = i;
    out.positions.push_back(mesh.positions[order[i]]);
  }
  for (const Triangle& t : mesh.triangles)
    out.triangles.push_back({number[t[0]], number[t[1]], number[t[2]]});
  return out;
}

}  // namespace

Mesh tile_base(const Surface& surface, const Settings& settings, const TileGrid& grid,
               const std::array<int, 3>& tile, std::span<const FaceCurves> faces, double edge) {
  check_tile_input(settings, grid, tile, faces, edge);
  const Box box = grid.tile_box(tile);
  Settings own = base_settings(settings, edge, 1);
  own.edge_length = edge;
  own.box = box;
  own.creases = Creases::Off;  // the driver refuses formulas with creases; here the surface is smooth
  Mesh raw;
  try {
    raw = mesh_surface(surface, own);
  } catch (const NoSurfaceError&) {
    // Nothing of the surface the tile's partition sees: its faces' curves, if any, are closed by fans.
  }
  raw.attributes.clear();
  const auto loops = blocks::tile_loops(faces);
  Mesh base = blocks::join_to_loops(raw, surface, loops, edge);
  if (base.triangles.empty()) return base;
  RemeshSettings clean =
      preset_remesh_settings(own, own.remesh_iterations.value_or(kDefaultRemeshIterations));
  clean.sizes.largest = edge;
  clean.box = box;
  clean.hold_cut = true;
  remesh_on_surface(base, surface, clean);
  base.attributes.clear();
  return cut_first(base);
}

}  // namespace isopatch
