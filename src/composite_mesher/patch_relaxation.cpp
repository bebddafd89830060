/// \file patch_relaxation.cpp
/// One patch remeshed on its own function with its boundary fixed (patch_relaxation.hpp).
#include "composite_mesher/patch_relaxation.hpp"

#include <isopatch/error.hpp>

#include <array>
#include <map>

namespace isopatch {

namespace {

using Key = std::array<double, 3>;
Key position_key(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace

PatchPiece relax_patch(const PatchPiece& piece, const std::vector<Vec3>& positions, const Surface& surface,
                       const RemeshSettings& settings, RemeshStats& stats) {
  if (piece.triangles.empty() || piece.points.empty()) return piece;
  // The local mesh: the boundary vertices the piece uses, in id order, then its own vertices.
  std::map<std::uint32_t, std::uint32_t> local_of;
  for (const Triangle& t : piece.triangles)
    for (const std::uint32_t id : t)
      if (id < PatchPiece::kLocalVertex) local_of.emplace(id, 0);
  Mesh mesh;
  std::map<Key, std::uint32_t> boundary_at;  // exact positions of the boundary vertices -> mesh ids
  for (auto& [id, local] : local_of) {
    local = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back(positions[id]);
    boundary_at.emplace(position_key(positions[id]), id);
  }
  const auto first_own = static_cast<std::uint32_t>(mesh.positions.size());
  for (const Vec3& p : piece.points) mesh.positions.push_back(p);
  for (const Triangle& t : piece.triangles) {
    Triangle local{};
    for (std::size_t i = 0; i < 3; ++i)
      local[i] =
          t[i] < PatchPiece::kLocalVertex ? local_of.at(t[i]) : first_own + (t[i] - PatchPiece::kLocalVertex);
    mesh.triangles.push_back(local);
  }
  const RemeshStats r = remesh_on_surface(mesh, surface, settings);
  stats.add_counts(r);
  // Back to mesh ids: a vertex at the exact position of a boundary vertex is that vertex (the remesher
  // keeps boundary vertices where they are); every other one is new.
  PatchPiece out;
  out.verdict = piece.verdict;
  out.gradient_rays = piece.gradient_rays;
  out.unprojected = piece.unprojected;
  std::vector<std::uint32_t> id_of(mesh.positions.size());
  std::size_t boundary_seen = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const auto it = boundary_at.find(position_key(mesh.positions[v]));
    if (it != boundary_at.end()) {
      id_of[v] = it->second;
      ++boundary_seen;
    } else {
      id_of[v] = PatchPiece::kLocalVertex + static_cast<std::uint32_t>(out.points.size());
      out.points.push_back(mesh.positions[v]);
    }
  }
  if (boundary_seen != boundary_at.size())
    throw Error(ErrorKind::Internal, "the clean-up of a patch lost one of its boundary vertices");
  for (const Triangle& t : mesh.triangles) out.triangles.push_back({id_of[t[0]], id_of[t[1]], id_of[t[2]]});
  return out;
}

}  // namespace isopatch
