/// \file composite_refinement.cpp
/// A composite's projection mesh refined (composite_refinement.hpp).
#include "composite_mesher/composite_refinement.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <string>
#include <utility>

#include "composite_mesher/curve_edge_points.hpp"
#include "refine/base_edges.hpp"
#include "refine/lattice_layout.hpp"

namespace isopatch {
void check_composite_parts(const Composite& composite, const Mesh& base,
                           const std::vector<std::uint32_t>& triangle_patch,
                           const std::vector<int>& curve_segments,
                           const std::vector<std::vector<std::uint32_t>>& curve_vertices) {
  const auto fail = [](const std::string& what) {
    throw InputError("refine: the composite mesh does not belong to the composite (" + what + ")");
  };
  if (triangle_patch.size() != base.triangle_count()) fail("a patch per triangle");
  if (curve_vertices.size() != composite.curves.size() || curve_segments.size() != composite.curves.size())
    fail("curves");
  for (const std::uint32_t p : triangle_patch)
    if (p >= composite.patches.size()) fail("patch numbers");
  for (std::size_t c = 0; c < curve_vertices.size(); ++c) {
    const auto& ids = curve_vertices[c];
    if (curve_segments[c] < 0 || curve_segments[c] > kMaxPatchResolution * refine::kMaxLevel)
      fail("curve segments");
    if (!ids.empty() && ids.size() != static_cast<std::size_t>(curve_segments[c]) + 1) fail("curve samples");
    for (const std::uint32_t v : ids)
      if (v >= base.vertex_count()) fail("curve vertex numbers");
  }
}

refine::RefineParams composite_refine_params(const refine::RefineParams& params) {
  // The curves' vertices are held where they are, many of valence 4 or 5; uniform-Laplacian moves of
  // their free neighbours pull those in and close the triangles at the curves (on the examples at k =
  // 2..4, smallest angles of 15 to 19 degrees against the base's 25), so the relaxation may not close a
  // triangle under the angle target further (23.9 to 28 degrees on the same).
  refine::RefineParams guarded = params;
  guarded.guard_angles = true;
  return guarded;
}

refine::RefineResult refine_composite(const Composite& composite, const CompositeMesh& base,
                                      const refine::RefineParams& params, CompositeMesh* refined) {
  check_composite_parts(composite, base.mesh, base.triangle_patch, base.curve_segments, base.curve_vertices);
  if (base.vertex_patch.size() != base.mesh.vertex_count())
    throw InputError("refine: the composite mesh does not belong to the composite (a patch per vertex)");
  const int k = params.level;
  refine::RefinePieces pieces;
  for (const CompositePatch& p : composite.patches) pieces.functions.push_back(p.surface.get());
  pieces.triangle_piece = base.triangle_patch;
  CurveEdgePoints curve_points(composite, base.curve_segments, base.curve_vertices);
  pieces.curve_points = [&](std::uint32_t a, std::uint32_t b, int level, std::span<Vec3> out) {
    return curve_points.points(a, b, level, out);
  };
  refine::RefineResult result = refine::refine_pieces(base.mesh, pieces, composite_refine_params(params));
  if (refined && result.failed_points == 0) {
    refined->mesh = result.mesh;
    refined->triangle_patch = result.triangle_piece;
    refined->vertex_patch = result.vertex_piece;
    refined->curve_segments = base.curve_segments;
    for (int& n : refined->curve_segments) n *= k;
    // A refined curve's vertices: its base samples with the points of each segment's edge between.
    const refine::BaseEdges edges = refine::base_edges(base.mesh);
    const refine::LatticeLayout layout(base.mesh, edges, k);
    refined->curve_vertices.assign(base.curve_vertices.size(), {});
    for (std::size_t c = 0; c < base.curve_vertices.size(); ++c) {
      const auto& ids = base.curve_vertices[c];
      auto& out = refined->curve_vertices[c];
      for (std::size_t i = 0; i + 1 < ids.size(); ++i) {
        const std::uint32_t a = ids[i], b = ids[i + 1];
        // base_edges() numbers the edges in ascending (lower, higher) order.
        const std::array<std::uint32_t, 2> key = {std::min(a, b), std::max(a, b)};
        const auto found = std::lower_bound(edges.ends.begin(), edges.ends.end(), key);
        if (found == edges.ends.end() || *found != key)
          throw Error(ErrorKind::Internal, "refine: a curve segment is not an edge of the composite mesh");
        const auto e = static_cast<std::uint32_t>(found - edges.ends.begin());
        out.push_back(a);
        for (int j = 1; j < k; ++j) out.push_back(layout.edge_point(e, a < b ? j : k - j));
      }
      if (!ids.empty()) out.push_back(ids.back());
    }
  }
  return result;
}

}  // namespace isopatch
