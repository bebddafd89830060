/// \file composite_assembly.cpp
/// Clean-up per patch and assembly of a composite's mesh (composite_assembly.hpp).
#include "composite_mesher/composite_assembly.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "composite_mesher/patch_relaxation.hpp"
#include "core/vertex_role.hpp"
#include "remesh/remesh_presets.hpp"

namespace isopatch {

std::vector<RemeshStats> clean_up_patches(const Composite& c, ProjectedPatches& patches,
                                          const Settings& settings, const TargetSizes& sizes,
                                          int iterations) {
  std::vector<PatchPiece>& pieces = patches.pieces;
  const CurveSampling& sampling = patches.sampling;
  const std::vector<bool>& fan = patches.fan;
  const std::size_t count = pieces.size();
  if (iterations > 0 && settings.max_vertices > 0 && !sizes.varies()) {
    // The clean-up splits towards the target size: refuse before it would exceed the vertex budget
    // (a mesh of equilateral triangles of side h has about area / (sqrt(3)/2 h^2) vertices).
    double area = 0.0;
    for (const PatchPiece& piece : pieces)
      for (const Triangle& t : piece.triangles) {
        const auto at = [&](std::uint32_t id) {
          return id < PatchPiece::kLocalVertex ? sampling.positions[id]
                                               : piece.points[id - PatchPiece::kLocalVertex];
        };
        area += 0.5 * (at(t[1]) - at(t[0])).cross(at(t[2]) - at(t[0])).norm();
      }
    settings.check_vertices(
        static_cast<std::size_t>(area / (0.5 * std::sqrt(3.0) * sizes.largest * sizes.largest)));
  }
  std::vector<RemeshStats> cleanup(count);
  if (iterations > 0) {
    // The preset's passes with these sizes.
    RemeshSettings rs = preset_remesh_settings(settings, iterations);
    rs.sizes = sizes;
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count), [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t p = r.begin(); p != r.end(); ++p)
            if (!fan[p])
              pieces[p] = relax_patch(pieces[p], sampling.positions, *c.patches[p].surface, rs, cleanup[p]);
        });
  }

  return cleanup;
}

CompositeMesh assemble_composite(const Composite& c, const ProjectedPatches& patches,
                                 const std::vector<int>& segments, const Settings& settings, bool cleaned_up,
                                 ProjectionStats& ps) {
  const std::vector<PatchPiece>& pieces = patches.pieces;
  const CurveSampling& sampling = patches.sampling;
  const std::vector<bool>& fan = patches.fan;
  const std::size_t count = pieces.size();
  CompositeMesh out;
  out.curve_segments = segments;
  out.curve_vertices = sampling.ids;
  out.mesh.positions = sampling.positions;
  out.vertex_patch.assign(sampling.positions.size(), -1);
  for (std::size_t p = 0; p < count; ++p) {
    const auto base = static_cast<std::uint32_t>(out.mesh.positions.size());
    settings.check_vertices(base + pieces[p].points.size());
    for (const Vec3& q : pieces[p].points) {
      out.mesh.positions.push_back(q);
      out.vertex_patch.push_back(static_cast<std::int32_t>(p));
    }
    for (const Triangle& t : pieces[p].triangles) {
      Triangle g{};
      for (std::size_t i = 0; i < 3; ++i)
        g[i] = t[i] < PatchPiece::kLocalVertex ? t[i] : base + (t[i] - PatchPiece::kLocalVertex);
      out.mesh.triangles.push_back(g);
      out.triangle_patch.push_back(static_cast<std::uint32_t>(p));
    }
    ps.gradient_rays += pieces[p].gradient_rays;
    ps.unprojected_vertices += pieces[p].unprojected;
    if (fan[p])
      ++ps.fallback_cells;
    else
      ++ps.patches_by_sides[static_cast<int>(c.patches[p].sides.size())];
  }
  if (settings.vertex_roles) {
    // What made each vertex (the values of core/vertex_role.hpp): corners, curve samples, patch
    // interiors (Remeshed where the clean-up has remeshed the patch), fan centres.
    std::vector<float> roles(out.mesh.vertex_count(), role_value(VertexRole::Interior));
    std::fill(roles.begin(), roles.begin() + static_cast<std::ptrdiff_t>(sampling.corners),
              role_value(VertexRole::Corner));
    std::fill(roles.begin() + static_cast<std::ptrdiff_t>(sampling.corners),
              roles.begin() + static_cast<std::ptrdiff_t>(sampling.positions.size()),
              role_value(VertexRole::Side));
    for (std::size_t v = sampling.positions.size(); v < roles.size(); ++v) {
      const auto p = static_cast<std::size_t>(out.vertex_patch[v]);
      if (fan[p])
        roles[v] = role_value(VertexRole::FanCentre);
      else if (cleaned_up)
        roles[v] = role_value(VertexRole::Remeshed);
    }
    out.mesh.set_attribute("role", std::move(roles));
  }
  return out;
}

}  // namespace isopatch
