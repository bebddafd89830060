/// \file crease_meshing.cpp
/// Formulas with creases meshed along them (crease_meshing.hpp).
#include "api/crease_meshing.hpp"

#include <isopatch/error.hpp>
#include <isopatch/topology.hpp>

#include <chrono>
#include <memory>
#include <utility>

namespace isopatch {

namespace {

/// The triangle angle floor (degrees) the repair aims over, with a margin.
constexpr double kCreaseAngleFloor = kExemptCornerDegrees;
constexpr double kCreaseAngleMargin = 2.0;
/// A vertex lies on a face within this share of the box diagonal (crease samples lie on both to
/// rounding; any other vertex is far from a second face); one the repair moves is put back on its
/// faces to the second.
constexpr double kCreaseOnFace = 1e-9;
constexpr double kCreaseRepairTolerance = 1e-14;

}  // namespace

std::optional<CsgShape> analyse_creases(const Surface& surface, const Settings& settings,
                                        std::optional<Vec3>* leaves_box) {
  if (settings.creases == Creases::Off || settings.method != Method::Projection || !settings.region.empty() ||
      settings.frame || !settings.cells.empty() || !surface.expression())
    return std::nullopt;
  const Box box = settings.box.value_or(surface.box());
  const TargetSizes sizes = target_sizes(settings, box);
  return analyse_csg(surface, box, sizes.largest, leaves_box);
}

AngleRepair repair_crease_angles(Mesh& mesh, const std::vector<SurfacePtr>& faces, const Box& box,
                                 const std::vector<std::uint8_t>* held) {
  return repair_small_angles(mesh, faces, kCreaseAngleFloor + kCreaseAngleMargin,
                             kCreaseOnFace * box.diagonal(), kCreaseRepairTolerance * box.diagonal(), held);
}

CreasedMesh mesh_along_creases(const Surface& surface, const Settings& settings, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<Vec3> leaves_box;
  std::optional<CsgShape> shape = analyse_creases(surface, settings, &leaves_box);
  if (!shape) return {std::nullopt, leaves_box.has_value()};
  const Box box = settings.box.value_or(surface.box());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const CompositeModel model(std::make_shared<const Composite>(std::move(shape->composite)));
  // A refinement is judged on the angles the last repair leaves (its triangles at the creases close
  // to 15-17 degrees before it); the repair runs once more on the mesh kept (level 1 needs it).
  const auto repair_refined = [&](Mesh& refined) {
    repair_crease_angles(refined, shape->face_functions, box);
  };
  Mesh mesh = mesh_composite_along_curves(model, settings, stats, repair_refined);
  // Triangles along the pieces' boundaries, which the per-piece clean-up holds, brought over the floor
  // where a seam vertex may move or a crease vertex slide.
  const AngleRepair repair = repair_crease_angles(mesh, shape->face_functions, box);
  const TopologyReport topology = analyze_topology(mesh);
  if (topology.non_manifold_edges > 0 || topology.non_manifold_vertices > 0 || topology.boundary_edges > 0)
    throw ShapeNotManifoldError(
        "the mesh along the shape's creases is not a closed 2-manifold (" +
        std::to_string(topology.non_manifold_edges) + " non-manifold edges, " +
        std::to_string(topology.non_manifold_vertices) + " non-manifold vertices, " +
        std::to_string(topology.boundary_edges) +
        " boundary edges): solids touching along an edge or at a point, or a sheet of zero "
        "thickness; --creases off meshes it as a smooth surface");
  if (stats) {
    CreaseStats c;
    c.faces = shape->faces;
    c.creases = shape->creases;
    c.corners = shape->corners;
    c.seams = shape->seams;
    c.pieces = model.patch_count();
    c.smooth_pairs = shape->smooth_pairs;
    c.repair_moves = repair.moved;
    c.interval_cells = shape->certificate.cells;
    c.interval_creases = shape->certificate.found;
    c.uncertain_cells = shape->certificate.uncertain;
    c.seconds = seconds;
    stats->creases = c;
    stats->seconds += seconds;
    stats->times.add("creases", seconds);
    stats->warnings.exempt_corners = shape->exempt_corners;
    stats->warnings.uncertain_crease_cells = shape->certificate.uncertain;
    stats->warnings.uncertain_crease_near = shape->certificate.first_uncertain;
  }
  return {std::move(mesh), false};
}

}  // namespace isopatch
