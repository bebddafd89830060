// A composite surface's base for a blocked run, and its blocks refined on the patches' functions
// (blocks.hpp): the same base and the same curve points as mesh_composite() along the curves
// (composite_refinement.hpp), cut into blocks like a base of one function (block_piece.hpp).
#include <isopatch/blocks.hpp>
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>

#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "api/composite_settings.hpp"
#include "api/multiresolution.hpp"
#include "api/task_arena_run.hpp"
#include "blocks/block_piece.hpp"
#include "composite_mesher/composite_mesher.hpp"
#include "composite_mesher/composite_refinement.hpp"
#include "composite_mesher/curve_edge_points.hpp"
#include "composite_mesher/patch_curvature.hpp"
#include "composite_model/budgeted_composite.hpp"
#include "refine/lattice_relaxation.hpp"

namespace isopatch {
namespace {

void check_blocked_composite_settings(const Settings& settings) {
  blocks::check_blocked_settings(settings);
  if (meshed_through_partition(settings))
    throw SettingError(settings.frame ? "frame" : (settings.region.empty() ? "cells" : "region"),
                       "blocks mesh a composite along its own curves: a region, a frame or given cells "
                       "mesh it through the partition, on one machine");
  refuse_octree_settings(settings);
}

/// Per base vertex: the patch of the lowest-numbered base triangle that uses it (what refine_pieces
/// takes for the whole base).
std::vector<std::uint32_t> whole_base_vertex_patch(const Mesh& base, const BasePatches& patches) {
  constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> out(base.vertex_count(), kUnset);
  for (std::size_t t = 0; t < base.triangle_count(); ++t)
    for (const std::uint32_t v : base.triangles[t])
      if (out[v] == kUnset) out[v] = patches.triangle_patch[t];
  for (std::uint32_t& p : out)
    if (p == kUnset) p = 0;
  return out;
}

}  // namespace

BlockBase block_base(const CompositeModel& model, const Settings& settings) {
  check_blocked_composite_settings(settings);
  return blocks::composite_block_base(model, settings);
}

BlockMesh refine_block(const CompositeModel& model, const BasePatches& patches, const Settings& settings,
                       const Mesh& base, const BlockPlan& plan, int block) {
  return blocks::refine_composite_block(model, patches, settings, base, plan, block, {});
}

namespace blocks {

BlockBase composite_block_base(const CompositeModel& model, const Settings& settings) {
  return run_in_task_arena(settings, nullptr, [&] {
    std::optional<BudgetedComposite> budgeted;
    if (settings.max_evaluations > 0 || settings.time_limit > 0.0)
      budgeted.emplace(model.composite(), settings.max_evaluations, settings.time_limit);
    const Composite& c = budgeted ? budgeted->composite() : model.composite();
    const Box box = settings.box.value_or(model.surface()->box());
    const double edge = default_edge_length(settings, box);
    BlockBase out;
    std::vector<std::int32_t> vertex_patch;
    const auto make = [&](int level) {
      Settings at = base_settings(settings, edge, level);
      if (!composite_refines(settings))
        at = settings;  // one process meshes it once, at the settings themselves
      CompositeMesh made = mesh_composite_projection(c, at);
      out.base = std::move(made.mesh);
      out.patches.triangle_patch = std::move(made.triangle_patch);
      out.patches.curve_segments = std::move(made.curve_segments);
      out.patches.curve_vertices = std::move(made.curve_vertices);
      vertex_patch = std::move(made.vertex_patch);
    };
    out.level = composite_refines(settings) ? first_level(settings, edge, nullptr) : 1;
    make(out.level);
    if (level_from_curvature(settings) && out.level > 1) {
      const double kappa = largest_patch_curvature(c, vertex_patch, out.base);
      const int resolved = resolved_level(settings, edge, kappa, out.base.vertex_count(), out.level);
      if (resolved < out.level) {
        out.level = resolved;
        make(out.level);
      }
    }
    return out;
  });
}

BlockMesh refine_composite_block(const CompositeModel& model, const BasePatches& patches,
                                 const Settings& settings, const Mesh& base, const BlockPlan& plan, int block,
                                 const PieceFinisher& finish) {
  const Composite& c = model.composite();
  check_composite_parts(c, base, patches.triangle_patch, patches.curve_segments, patches.curve_vertices);
  const blocks::BlockPiece piece = blocks::block_piece(base, plan, block);
  refine::RefinePieces pieces;
  for (const CompositePatch& p : c.patches) pieces.functions.push_back(p.surface.get());
  for (const std::uint32_t t : piece.triangles) pieces.triangle_piece.push_back(patches.triangle_patch[t]);
  const std::vector<std::uint32_t> vertex_patch = whole_base_vertex_patch(base, patches);
  for (const std::uint32_t v : piece.vertices) pieces.vertex_piece.push_back(vertex_patch[v]);
  // The curves are looked up by base vertex numbers: the piece's numbers keep their order (a < b).
  CurveEdgePoints curve_points(c, patches.curve_segments, patches.curve_vertices);
  pieces.curve_points = [&](std::uint32_t a, std::uint32_t b, int level, std::span<Vec3> out) {
    return curve_points.points(piece.vertices[a], piece.vertices[b], level, out);
  };
  return blocks::refine_piece(
      settings, settings.box.value_or(model.surface()->box()), base, plan, block, piece,
      [&](const Mesh& mesh, const refine::RefineParams& params) {
        return refine::refine_pieces(mesh, pieces, composite_refine_params(params));
      },
      refine::smallest_angle_degrees(base), finish);
}

}  // namespace blocks
}  // namespace isopatch
