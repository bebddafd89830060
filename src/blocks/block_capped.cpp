// A capped, shelled or sheet lattice meshed as blocks (blocks.hpp): the parts one process meshes it as
// (api/capped_meshing.hpp, api/sheet_meshing.hpp), each part's cut surface refined in blocks with the
// planes as its region, then closed by its caps on one machine (api/cut_and_caps.hpp).
#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/capped_meshing.hpp"
#include "api/cut_and_caps.hpp"
#include "api/sheet_meshing.hpp"
#include "blocks/block_piece.hpp"

namespace isopatch {

struct CappedPieces {
  std::vector<CappedPart> parts;
  struct Cut {
    std::size_t part = 0;
    SurfacePtr surface;
  };
  std::vector<Cut> cuts;  ///< in the order one process appends them
};

namespace {

/// The parts of `surface` appended to `out`: a sheet's walls' in turn, else its own capped parts.
/// False when it (or a wall) is not meshed along caps.
bool collect_parts(const Surface& surface, const Settings& settings, std::vector<CappedPart>& out) {
  if (const auto walls = sheet_walls(surface, settings)) {
    for (const SurfacePtr& wall : *walls)
      if (!collect_parts(*wall, settings, out)) return false;
    return true;
  }
  std::optional<std::vector<CappedPart>> parts = split_capped_parts(surface, settings);
  if (!parts) return false;
  for (CappedPart& p : *parts) out.push_back(std::move(p));
  return true;
}

/// The surfaces one process meshes `surface` as with `settings`: its walls' (in order) when it is a
/// sheet, else itself.
void expand_walls(const SurfacePtr& surface, const Settings& settings, std::size_t part,
                  std::vector<CappedPieces::Cut>& out) {
  if (const auto walls = sheet_walls(*surface, settings)) {
    for (const SurfacePtr& wall : *walls) expand_walls(wall, settings, part, out);
    return;
  }
  out.push_back({part, surface});
}

const CappedPieces::Cut& cut_of(const CappedPieces& pieces, std::size_t cut) {
  if (cut >= pieces.cuts.size())
    throw InputError("cut " + std::to_string(cut) + " is not one of this capped shape's " +
                         std::to_string(pieces.cuts.size()) + " cut surfaces",
                     "part");
  return pieces.cuts[cut];
}

}  // namespace

std::shared_ptr<const CappedPieces> capped_pieces(const Surface& surface, const Settings& settings) {
  blocks::check_blocked_settings(settings);
  if (!settings.region.empty() || !settings.cells.empty()) return nullptr;
  CappedPieces pieces;
  if (!collect_parts(surface, settings, pieces.parts) || pieces.parts.empty()) return nullptr;
  for (std::size_t p = 0; p < pieces.parts.size(); ++p)
    if (pieces.parts[p].smooth)
      expand_walls(pieces.parts[p].smooth, cut_settings(pieces.parts[p], settings), p, pieces.cuts);
  return std::make_shared<const CappedPieces>(std::move(pieces));
}

std::size_t capped_part_count(const CappedPieces& pieces) {
  return pieces.parts.size();
}

std::vector<std::size_t> capped_cut_parts(const CappedPieces& pieces) {
  std::vector<std::size_t> out;
  for (const CappedPieces::Cut& c : pieces.cuts) out.push_back(c.part);
  return out;
}

BlockBase block_base(const CappedPieces& pieces, std::size_t cut, const Settings& settings) {
  const CappedPieces::Cut& c = cut_of(pieces, cut);
  const CappedPart& p = pieces.parts[c.part];
  check_caps_fit(p, settings);
  return block_base(*c.surface, cut_settings(p, settings));
}

BlockMesh refine_block(const CappedPieces& pieces, std::size_t cut, const Settings& settings,
                       const Mesh& base, const BlockPlan& plan, int block) {
  const CappedPieces::Cut& c = cut_of(pieces, cut);
  return refine_block(*c.surface, cut_settings(pieces.parts[c.part], settings), base, plan, block);
}

Mesh close_capped(const CappedPieces& pieces, std::vector<Mesh> cuts, const Settings& settings,
                  MeshStats* stats) {
  if (cuts.size() != pieces.cuts.size())
    throw InputError("a capped shape of " + std::to_string(pieces.cuts.size()) + " cut surfaces was given " +
                         std::to_string(cuts.size()) + " meshes",
                     "parts");
  // Each part's cut: its surfaces' meshes appended in order, as one process's sheet appends its walls.
  std::vector<Mesh> part_cuts(pieces.parts.size());
  for (std::size_t c = 0; c < cuts.size(); ++c) {
    Mesh& into = part_cuts[pieces.cuts[c].part];
    into = append_capped_part(std::move(into), cuts[c], false);
  }
  Mesh mesh;
  std::optional<CreaseStats> creases;
  double seconds = 0.0;
  for (std::size_t i = 0; i < part_cuts.size(); ++i) {
    const CappedPart& p = pieces.parts[i];
    MeshStats own;
    const Mesh closed = close_cut_with_caps(std::move(part_cuts[i]), p, settings, &own, 0.0);
    mesh = append_capped_part(std::move(mesh), closed, p.reversed);
    if (own.creases) {
      seconds += own.creases->seconds;
      if (!creases) {
        creases = own.creases;
      } else {
        creases->faces += own.creases->faces;
        creases->pieces += own.creases->pieces;
        creases->caps += own.creases->caps;
        creases->crease_vertices += own.creases->crease_vertices;
        creases->repair_moves += own.creases->repair_moves;
      }
    }
  }
  if (stats) {
    if (creases) creases->seconds = seconds;
    stats->creases = creases;
    stats->times.add("caps", seconds);
    stats->seconds += seconds;
    stats->vertices = mesh.vertex_count();
    stats->triangles = mesh.triangle_count();
  }
  return mesh;
}

}  // namespace isopatch
