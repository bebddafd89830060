// The base a blocked run refines, and its level (blocks.hpp).
#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/mesh_stats.hpp>

#include "api/multiresolution.hpp"
#include "api/size_estimate.hpp"
#include "blocks/block_piece.hpp"
#include "refine/refinement_level.hpp"

namespace isopatch {
namespace blocks {

void check_blocked_settings(const Settings& settings) {
  settings.validate();
  if (settings.method != Method::Projection)
    throw SettingError("method", "blocks refine the projection mesher's base: use the projection method");
  if (settings.frame)
    throw SettingError("frame", "blocks do not take a frame (mesh the surface on one machine)");
}

}  // namespace blocks

BlockBase block_base(const Surface& surface, const Settings& settings) {
  blocks::check_blocked_settings(settings);
  const Box box = settings.box.value_or(surface.box());
  const double edge = default_edge_length(settings, box);
  BlockBase out;
  const bool automatic = level_from_curvature(settings);
  SizeEstimate estimate;
  if (automatic) estimate = estimate_size(surface, settings, box, true);
  const auto make = [&](int level) {
    MeshStats stats;
    Mesh base = mesh_surface(surface, base_settings(settings, edge, level), &stats);
    if (stats.creases)
      throw SettingError(
          "creases",
          "this formula is meshed along its exact creases: make its blocks from creased_pieces() "
          "(or mesh it as a smooth surface with creases off)");
    return base;
  };
  out.level = first_level(settings, edge, automatic ? &estimate : nullptr);
  out.base = make(out.level);
  if (automatic && out.level > 1) {
    const double kappa = refine::largest_curvature(out.base.positions, surface);
    const int resolved = resolved_level(settings, edge, kappa, out.base.vertex_count(), out.level);
    if (resolved < out.level) {
      out.level = resolved;
      out.base = make(out.level);
    }
  }
  return out;
}

}  // namespace isopatch
