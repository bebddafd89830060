// Self-intersection test of a triangle mesh (see include/isopatch/self_intersection.hpp): a bounding
// volume hierarchy over the triangles' boxes, traversed against itself so that every pair of
// overlapping boxes is met once (triangle_tree.hpp); each such pair is decided exactly
// (triangle_pair.hpp). Subtrees of the hierarchy proved to be flat discs (flat_discs.hpp: patches that
// one coordinate projection maps one-to-one) are not scanned within; of the other pairs, those around a
// vertex whose fan is proved to meet itself only where it shares (flat_fans.hpp) are skipped.
#include <isopatch/error.hpp>
#include <isopatch/self_intersection.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/flat_discs.hpp"
#include "analysis/flat_fans.hpp"
#include "analysis/mesh_neighbourhood.hpp"
#include "analysis/triangle_pair.hpp"
#include "analysis/triangle_tree.hpp"
#include "core/default_init_allocator.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace isopatch {
namespace {

/// Whether s and t share a vertex whose fan is proved to meet itself only in shared vertices and edges
/// (flat_fans.hpp): then the pair does not meet otherwise.
bool share_a_flat_fan(const Triangle& s, const Triangle& t, const std::vector<std::uint8_t>& flat) {
  for (const std::uint32_t v : s)
    if (flat[v] != 0 && (v == t[0] || v == t[1] || v == t[2])) return true;
  return false;
}

/// Triangles per piece of the parallel pair scan: a few dozen pieces on a 20k-vertex mesh.
constexpr std::size_t kTrianglesPerJob = 1024;
/// Subtrees of fewer triangles are not tried as flat discs: the pairs within them cost less to scan.
constexpr std::size_t kSmallestDisc = 64;

/// The tree over `order` with its subtrees that are flat discs (flat_discs.hpp) marked: no pair within
/// them meets. Appends to `boundary` the vertices on those subtrees' boundaries.
analysis::TriangleTree proved_tree(const Mesh& mesh, const analysis::MeshFans& fans,
                                   std::vector<std::uint32_t> order, std::vector<std::uint32_t>& boundary) {
  analysis::TriangleTree tree(mesh, std::move(order), &fans.triangle_turns);
  UninitialisedVector<std::uint32_t> position(mesh.triangles.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, position.size(), 1U << 14U), [&](const auto& range) {
    for (std::size_t t = range.begin(); t != range.end(); ++t)
      position[t] = std::numeric_limits<std::uint32_t>::max();
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tree.order().size(), 1U << 14U),
                    [&](const auto& range) {
                      for (std::size_t p = range.begin(); p != range.end(); ++p)
                        position[tree.order()[p]] = static_cast<std::uint32_t>(p);
                    });
  const analysis::OrderedTriangles ordered{&mesh, &fans, &tree.order(), position.data()};
  tbb::enumerable_thread_specific<std::vector<std::uint32_t>> found;
  tree.prove_subtrees(
      [&](std::uint32_t begin, std::uint32_t end, std::uint8_t turns) {
        return analysis::flat_disc(ordered, begin, end, turns, &found.local());
      },
      kSmallestDisc);
  for (const std::vector<std::uint32_t>& part : found)
    boundary.insert(boundary.end(), part.begin(), part.end());
  return tree;
}

/// 1 for the vertices of `mesh` whose fans flat_fans.hpp proves among those where a pair sharing them
/// can still be scanned: on the boundary of a proved subtree or in a leaf outside them; 0 elsewhere.
std::vector<std::uint8_t> flat_fans_where_scanned(const Mesh& mesh, const analysis::MeshFans& fans,
                                                  const analysis::TriangleTree& tree,
                                                  const std::vector<std::uint32_t>& boundary) {
  std::vector<std::uint8_t> flat(mesh.positions.size(), 0);  // 2: to be decided
  for (const std::uint32_t v : boundary) flat[v] = 2;
  tree.for_each_unproved_leaf([&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t p = begin; p < end; ++p)
      for (const std::uint32_t v : mesh.triangles[tree.order()[p]]) flat[v] = 2;
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, flat.size(), 4096), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v)
      if (flat[v] == 2) flat[v] = analysis::flat_fan(mesh, fans, static_cast<std::uint32_t>(v)) ? 1 : 0;
  });
  return flat;
}

}  // namespace

SelfIntersectionReport find_self_intersections(const Mesh& mesh, std::size_t limit) {
  analysis::check_mesh(mesh, "find_self_intersections");
  if (mesh.triangles.size() >= std::numeric_limits<std::uint32_t>::max())
    throw InputError("find_self_intersections: more than 2^32 triangles");
  SelfIntersectionReport report;
  if (limit == 0) return report;
  // The fans first: their incidence lists are freed before the tree is made.
  analysis::MeshFans fans = analysis::mesh_fans(mesh);
  // The tree in the mesh's own order when that keeps neighbours together; in Z-order when it does not,
  // or when its subtrees are not flat discs (a mesh written in strips that wind around a tube).
  std::vector<std::uint32_t> own = analysis::own_order(mesh);
  const bool local = analysis::keeps_neighbours_together(mesh, own);
  std::optional<analysis::TriangleTree> tree;
  std::vector<std::uint32_t> boundary;
  tree.emplace(
      proved_tree(mesh, fans, local ? std::move(own) : analysis::z_ordered_triangles(mesh), boundary));
  if (local && 2 * tree->proved_triangles() < tree->order().size()) {
    boundary.clear();
    tree.emplace(proved_tree(mesh, fans, analysis::z_ordered_triangles(mesh), boundary));
  }
  const std::vector<std::uint8_t> flat = flat_fans_where_scanned(mesh, fans, *tree, boundary);
  // The proofs' data freed before the boxes are made.
  fans = analysis::MeshFans{};
  boundary = {};
  tree->make_boxes();
  // The scan in pieces, in parallel; each piece counts its own pairs (up to the limit) and keeps its
  // first. In the pieces' order, the first piece with a pair has the scan's first pair: the same report
  // as one scan, for any number of threads.
  struct Found {
    std::size_t pairs = 0;
    std::array<std::size_t, 2> example{};
    Vec3 at = Vec3::Zero();
  };
  const std::vector<analysis::TriangleTree::Job> jobs = tree->jobs(kTrianglesPerJob);
  std::vector<Found> found(jobs.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, jobs.size(), 1), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      Found& f = found[k];
      tree->run(jobs[k], [&](std::size_t a, std::size_t b) {
        const std::size_t i = tree->triangle(a), j = tree->triangle(b);
        if (share_a_flat_fan(mesh.triangles[i], mesh.triangles[j], flat)) return true;
        Vec3 at;
        if (!analysis::triangles_meet(mesh, mesh.triangles[i], mesh.triangles[j], &at)) return true;
        if (f.pairs++ == 0) {
          f.example = {std::min(i, j), std::max(i, j)};
          f.at = at;
        }
        return f.pairs < limit;
      });
    }
  });
  std::size_t total = 0;
  for (const Found& f : found) {
    if (total == 0 && f.pairs > 0) {
      report.example = f.example;
      report.example_point = f.at;
    }
    total += f.pairs;
  }
  report.pairs = std::min(total, limit);
  report.capped = total >= limit;
  return report;
}

}  // namespace isopatch
