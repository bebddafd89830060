// How a surface is meshed in tiles, and one tile's task (tiles.hpp).
#include <isopatch/error.hpp>
#include <isopatch/tiles.hpp>

#include <string>

#include "api/multiresolution.hpp"
#include "api/size_estimate.hpp"
#include "blocks/block_piece.hpp"

namespace isopatch {
namespace {

/// The narrowest tile a plan makes, in base edges.
constexpr double kNarrowestTile = 8.0;

}  // namespace

namespace blocks {

void check_tiled_settings(const Settings& settings) {
  blocks::check_blocked_settings(settings);
  if (!settings.region.empty() || !settings.cells.empty())
    throw SettingError("region", "tiles by planes take the box alone (no region or cells)");
  if (settings.max_error || settings.size_field)
    throw SettingError("max_error", "tiles by planes mesh at one edge length (no error bound or size field)");
}

}  // namespace blocks

TilePlan plan_tiles(const Surface& surface, const Settings& settings, int tiles) {
  blocks::check_tiled_settings(settings);
  const Box box = settings.box.value_or(surface.box());
  TilePlan plan;
  plan.edge = default_edge_length(settings, box);
  const bool automatic = level_from_curvature(settings);
  const SizeEstimate estimate = estimate_size(surface, settings, box, automatic);
  plan.estimated_vertices = estimate.vertices;
  plan.level = first_level(settings, plan.edge, automatic ? &estimate : nullptr);
  const std::array<int, 3> counts = tile_counts(box, tiles);
  // A tile narrower than a few base edges is mostly cut: its base cannot relax between its faces.
  for (int a = 0; a < 3; ++a)
    if (box.size()[a] / counts[static_cast<std::size_t>(a)] < kNarrowestTile * plan.spacing())
      throw SettingError("tiles", std::to_string(counts[0] * counts[1] * counts[2]) +
                                      " tiles of this box would be narrower than " +
                                      std::to_string(static_cast<int>(kNarrowestTile)) + " base edges (" +
                                      std::to_string(plan.spacing()) +
                                      "): use fewer tiles, a smaller edge, or blocks of one base");
  plan.grid = clear_tile_grid(surface, box, counts, 0.4 * plan.spacing());
  return plan;
}

TileMesh mesh_tile(const Surface& surface, const Settings& settings, const TilePlan& plan,
                   const std::array<int, 3>& tile, std::span<const FaceCurves> faces) {
  const Mesh base = tile_base(surface, settings, plan.grid, tile, faces, plan.spacing());
  return refine_tile(surface, settings, plan.grid, tile, base, plan.level);
}

}  // namespace isopatch
