// A sheet meshed as its two walls (sheet_meshing.hpp).
#include "api/sheet_meshing.hpp"

#include <cstddef>
#include <optional>

#include "csg/sheet_shape.hpp"

namespace isopatch {

std::optional<std::array<SurfacePtr, 2>> sheet_walls(const Surface& f, const Settings& settings) {
  if (settings.method != Method::Projection) return std::nullopt;
  const std::optional<SheetShape> sheet = split_sheet_shape(f, apart_domain(f, settings));
  if (!sheet) return std::nullopt;
  return sheet->walls;
}

std::optional<Mesh> mesh_sheet(const Surface& f, const Settings& settings, MeshStats* stats,
                               const WallMesher& mesh_wall) {
  const std::optional<std::array<SurfacePtr, 2>> sheet = sheet_walls(f, settings);
  if (!sheet) return std::nullopt;
  const ApartSurface walls[2] = {{(*sheet)[0], nullptr, 0}, {(*sheet)[1], nullptr, 0}};
  std::size_t surfaces = 0;
  Mesh mesh = mesh_apart_surfaces(walls, settings, stats, mesh_wall, &surfaces);
  if (stats) stats->sheet = SheetStats{surfaces};
  return mesh;
}

}  // namespace isopatch
