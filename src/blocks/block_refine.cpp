// One block of a blocked base refined on its own, its output in the whole output's numbers (blocks.hpp,
// block_piece.hpp).
#include <isopatch/error.hpp>
#include "blocks/block_piece.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "api/multiresolution.hpp"
#include "api/task_arena_run.hpp"
#include "refine/base_edges.hpp"
#include "refine/lattice_layout.hpp"
#include "refine/lattice_relaxation.hpp"
#include "refine/refine_mesh.hpp"

namespace isopatch {
namespace blocks {
namespace {

constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();

/// The edge from a to b (a < b) in `ends` (sorted ascending). \pre it is one of them.
std::uint32_t find_edge(const std::vector<std::array<std::uint32_t, 2>>& ends, std::uint32_t a,
                        std::uint32_t b) {
  const std::array<std::uint32_t, 2> key{a, b};
  return static_cast<std::uint32_t>(std::lower_bound(ends.begin(), ends.end(), key) - ends.begin());
}

void check_block_input(const Mesh& base, const BlockPlan& plan, int block) {
  if (block < 0 || block >= plan.blocks)
    throw InputError("block " + std::to_string(block) + " is not one of the plan's " +
                         std::to_string(plan.blocks) + " blocks",
                     "block");
  if (plan.triangle_block.size() != base.triangle_count() ||
      plan.vertex_number.size() != base.vertex_count() ||
      plan.first_vertex.size() != static_cast<std::size_t>(plan.blocks))
    throw InputError("the block plan was made for another base", "block");
}

}  // namespace

BlockPiece block_piece(const Mesh& base, const BlockPlan& plan, int block) {
  check_block_input(base, plan, block);
  BlockPiece piece;
  std::vector<std::uint32_t> local(base.vertex_count(), kUnused);
  for (std::size_t t = 0; t < base.triangle_count(); ++t)
    if (plan.triangle_block[t] == static_cast<std::uint32_t>(block)) {
      piece.triangles.push_back(static_cast<std::uint32_t>(t));
      for (const std::uint32_t v : base.triangles[t]) local[v] = 0;
    }
  for (std::size_t v = 0; v < base.vertex_count(); ++v)
    if (local[v] != kUnused) {
      local[v] = static_cast<std::uint32_t>(piece.vertices.size());
      piece.vertices.push_back(static_cast<std::uint32_t>(v));
      piece.mesh.positions.push_back(base.positions[v]);
    }
  for (const std::uint32_t t : piece.triangles) {
    const Triangle& tri = base.triangles[t];
    piece.mesh.triangles.push_back({local[tri[0]], local[tri[1]], local[tri[2]]});
  }
  return piece;
}

BlockMesh refine_piece(const Settings& settings, const Box& box, const Mesh& base, const BlockPlan& plan,
                       int block, const BlockPiece& piece, const PieceRefiner& refine,
                       std::optional<double> base_smallest_angle, const PieceFinisher& finish) {
  const refine::BaseEdges local_edges = refine::base_edges(piece.mesh);
  // Per local edge: the base edge it is, and whether it is a seam with another block.
  std::vector<std::uint32_t> global_edge(local_edges.size());
  std::vector<std::uint8_t> seam(local_edges.size());
  for (std::size_t e = 0; e < local_edges.size(); ++e) {
    global_edge[e] = find_edge(plan.edge_ends, piece.vertices[local_edges.ends[e][0]],
                               piece.vertices[local_edges.ends[e][1]]);
    seam[e] = plan.edge_between_blocks[global_edge[e]];
  }

  const int k = plan.level;
  refine::RefineParams params = refine_params(settings, box, k);
  params.max_vertices = 0;  // the whole output's budget is the caller's (BlockPlan::vertices)
  params.scale = std::max(bounding_box(base).diagonal(), 1e-300);
  params.seam = [&](std::uint32_t a, std::uint32_t b) {
    return seam[find_edge(local_edges.ends, a, b)] != 0;
  };
  refine::RefineResult refined =
      run_in_task_arena(settings, nullptr, [&] { return refine(piece.mesh, params); });
  BlockMesh out;
  out.block = block;
  out.failed_points = refined.failed_points;
  if (refined.failed_points > 0) return out;
  // Local numbers (refine/lattice_layout.hpp): base vertices, edge points from the lower end, inner
  // points per triangle.
  const refine::LatticeLayout layout(piece.mesh, local_edges, k);
  if (finish) {
    // The vertices on seams stay: the ends and points of every seam edge.
    std::vector<std::uint8_t> held(refined.mesh.vertex_count(), 0);
    for (std::uint32_t e = 0; e < local_edges.size(); ++e) {
      if (!seam[e]) continue;
      held[local_edges.ends[e][0]] = held[local_edges.ends[e][1]] = 1;
      for (int j = 1; j < k; ++j) held[layout.edge_point(e, j)] = 1;
    }
    run_in_task_arena(settings, nullptr, [&] {
      finish(refined.mesh, held);
      return 0;
    });
    refined.smallest_angle = refine::smallest_angle_degrees(refined.mesh);
  }
  // Kept as one process keeps it: on the angles the last pass leaves.
  out.smallest_angle = refined.smallest_angle;
  out.kept = base_smallest_angle ? refinement_kept(settings, refined.smallest_angle, *base_smallest_angle)
                                 : refinement_kept(settings, refined.smallest_angle);

  // The output number of every local vertex, from the plan.
  std::vector<std::uint64_t> id(refined.mesh.vertex_count());
  for (std::size_t v = 0; v < piece.vertices.size(); ++v) id[v] = plan.vertex_number[piece.vertices[v]];
  for (std::uint32_t e = 0; e < local_edges.size(); ++e)
    for (int j = 1; j < k; ++j)
      id[layout.edge_point(e, j)] =
          plan.edge_first_number[global_edge[e]] + static_cast<std::uint64_t>(j - 1);
  for (std::size_t t = 0; t < piece.triangles.size(); ++t)
    for (std::size_t m = 0; m < layout.inner_per_triangle(); ++m)
      id[layout.inner_start(t) + m] = plan.triangle_first_inner[piece.triangles[t]] + m;

  const auto b = static_cast<std::size_t>(block);
  out.positions.resize(plan.vertex_count[b]);
  const std::uint64_t first = plan.first_vertex[b], end = first + plan.vertex_count[b];
  for (std::size_t v = 0; v < id.size(); ++v) {
    if (id[v] >= first && id[v] < end) {
      out.positions[id[v] - first] = refined.mesh.positions[v];
    } else {
      out.seam_ids.push_back(id[v]);
      out.seam_positions.push_back(refined.mesh.positions[v]);
    }
  }
  out.triangles.reserve(refined.mesh.triangle_count());
  for (const Triangle& t : refined.mesh.triangles) out.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});

  // The seam band: the output vertices of base triangles with a corner on a seam.
  std::vector<std::uint8_t> on_seam(piece.vertices.size(), 0);
  for (std::uint32_t e = 0; e < local_edges.size(); ++e)
    if (seam[e]) on_seam[local_edges.ends[e][0]] = on_seam[local_edges.ends[e][1]] = 1;
  std::vector<std::uint8_t> band(refined.mesh.vertex_count(), 0);
  const auto kk = static_cast<std::size_t>(k * k);
  for (std::size_t t = 0; t < piece.triangles.size(); ++t) {
    const Triangle& tri = piece.mesh.triangles[t];
    if (!on_seam[tri[0]] && !on_seam[tri[1]] && !on_seam[tri[2]]) continue;
    for (std::size_t i = 0; i < kk; ++i)
      for (const std::uint32_t v : refined.mesh.triangles[t * kk + i]) band[v] = 1;
  }
  out.seam_band_vertices = static_cast<std::size_t>(std::count(band.begin(), band.end(), std::uint8_t{1}));
  return out;
}

}  // namespace blocks

BlockMesh refine_block(const Surface& surface, const Settings& settings, const Mesh& base,
                       const BlockPlan& plan, int block) {
  const blocks::BlockPiece piece = blocks::block_piece(base, plan, block);
  return blocks::refine_piece(
      settings, settings.box.value_or(surface.box()), base, plan, block, piece,
      [&](const Mesh& mesh, const refine::RefineParams& params) {
        return refine::refine_mesh(mesh, surface, params);
      },
      std::nullopt);
}

}  // namespace isopatch
