/// \file composite_refinement.cpp
/// A composite's projection mesh refined (composite_refinement.hpp).
#include "composite_mesher/composite_refinement.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>

#include "composite_mesher/curve_samples.hpp"
#include "refine/base_edges.hpp"
#include "refine/lattice_layout.hpp"

namespace isopatch {
namespace {

/// A base edge on a curve: the curve, the segment (between its samples i and i + 1) and whether the
/// edge's lower vertex is sample i.
struct CurveSegment {
  std::uint32_t curve = 0;
  int segment = 0;
  bool lower_first = true;
};

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;

std::map<EdgeKey, CurveSegment> curve_segments_by_edge(const CompositeMesh& base) {
  std::map<EdgeKey, CurveSegment> by_edge;
  for (std::size_t c = 0; c < base.curve_vertices.size(); ++c) {
    const std::vector<std::uint32_t>& ids = base.curve_vertices[c];
    for (std::size_t i = 0; i + 1 < ids.size(); ++i) {
      const std::uint32_t a = ids[i], b = ids[i + 1];
      by_edge[{std::min(a, b), std::max(a, b)}] =
          CurveSegment{static_cast<std::uint32_t>(c), static_cast<int>(i), a < b};
    }
  }
  return by_edge;
}

void check_base(const Composite& composite, const CompositeMesh& base) {
  const auto fail = [](const std::string& what) {
    throw InputError("refine: the composite mesh does not belong to the composite (" + what + ")");
  };
  if (base.triangle_patch.size() != base.mesh.triangle_count()) fail("a patch per triangle");
  if (base.vertex_patch.size() != base.mesh.vertex_count()) fail("a patch per vertex");
  if (base.curve_vertices.size() != composite.curves.size() ||
      base.curve_segments.size() != composite.curves.size())
    fail("curves");
  for (const std::uint32_t p : base.triangle_patch)
    if (p >= composite.patches.size()) fail("patch numbers");
  for (std::size_t c = 0; c < base.curve_vertices.size(); ++c) {
    const auto& ids = base.curve_vertices[c];
    if (!ids.empty() && ids.size() != static_cast<std::size_t>(base.curve_segments[c]) + 1)
      fail("curve samples");
    for (const std::uint32_t v : ids)
      if (v >= base.mesh.vertex_count()) fail("curve vertex numbers");
  }
}

}  // namespace

refine::RefineResult refine_composite(const Composite& composite, const CompositeMesh& base,
                                      const refine::RefineParams& params, CompositeMesh* refined) {
  check_base(composite, base);
  const int k = params.level;
  refine::RefinePieces pieces;
  for (const CompositePatch& p : composite.patches) pieces.functions.push_back(p.surface.get());
  pieces.triangle_piece = base.triangle_patch;
  const std::map<EdgeKey, CurveSegment> by_edge = curve_segments_by_edge(base);
  // Each curve sampled once at k times its segments, when an edge first asks (curve_points is called
  // from one thread).
  std::map<std::uint32_t, std::vector<Vec3>> fine;
  pieces.curve_points = [&](std::uint32_t a, std::uint32_t b, int level, std::span<Vec3> out) {
    const auto it = by_edge.find({a, b});
    if (it == by_edge.end()) return false;
    const CurveSegment& s = it->second;
    auto [at, fresh] = fine.try_emplace(s.curve);
    if (fresh) at->second = sample_curve(composite, s.curve, base.curve_segments[s.curve] * level);
    const std::vector<Vec3>& samples = at->second;
    // Sample i * level + j lies j / level of the way along segment i, from sample i.
    for (int j = 1; j < level; ++j) {
      const int along = s.lower_first ? j : level - j;
      out[static_cast<std::size_t>(j - 1)] = samples[static_cast<std::size_t>(s.segment * level + along)];
    }
    return true;
  };
  // The curves' vertices are held where they are, many of valence 4 or 5; uniform-Laplacian moves of
  // their free neighbours pull those in and close the triangles at the curves (on the examples at k =
  // 2..4, smallest angles of 15 to 19 degrees against the base's 25), so the relaxation may not close a
  // triangle under the angle target further (23.9 to 28 degrees on the same).
  refine::RefineParams guarded = params;
  guarded.guard_angles = true;
  refine::RefineResult result = refine::refine_pieces(base.mesh, pieces, guarded);
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
