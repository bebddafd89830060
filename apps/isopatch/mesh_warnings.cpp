// Warnings of `isopatch mesh` (see mesh_warnings.hpp).
#include "mesh_warnings.hpp"

#include <isopatch/metrics.hpp>
#include <isopatch/self_intersection.hpp>

#include <string>

namespace isopatch::cli {

void print_mesh_warnings(const MeshStats& stats, const Mesh& mesh, const SelfIntersectionReport& crossings,
                         std::FILE* out) {
  const MeshWarnings& w = stats.warnings;
  const std::size_t doubtful = w.doubtful_topology_cells;
  if (doubtful > 0)
    std::fprintf(out,
                 "warning: %zu cells at the depth limit %d (side %.3g) still hold two sheets of f = 0, an "
                 "ambiguous face or edges crossed twice: sheets closer than that may be joined or dropped "
                 "there (a larger --max-depth looks finer)\n",
                 doubtful, w.depth_limit, w.doubtful_cell_size);
  if (w.fan_patches > 0)
    std::fprintf(
        out,
        "warning: %zu patches of the composite were still rejected after refining their curves and "
        "are closed by fans over their boundaries (%zu fan centres off the surface): their functions "
        "leave their regions or fold there\n",
        w.fan_patches, w.unprojected_fan_centres);
  if (w.exempt_corners > 0)
    std::fprintf(out,
                 "warning: %zu corners of the shape's faces are sharper than 25 degrees: the triangles at "
                 "those corners cannot reach the 25 degree floor\n",
                 w.exempt_corners);
  if (w.uncertain_crease_cells > 0)
    std::fprintf(out,
                 "warning: %zu small cells, the first near (%.6g, %.6g, %.6g), may hold a crease by interval "
                 "arithmetic, but no crease was found in them: a feature much smaller than an edge may be "
                 "missing there (a smaller --edge-length searches finer)\n",
                 w.uncertain_crease_cells, w.uncertain_crease_near.x(), w.uncertain_crease_near.y(),
                 w.uncertain_crease_near.z());
  if (w.creases_leave_box > 0)
    std::fprintf(
        out,
        "warning: creases of the shape leave the box, and the shape cut open by the box could not be "
        "meshed along them: meshed as a smooth surface (creases rounded); a box that holds the whole "
        "shape meshes it along its creases\n");
  if (w.creases_rounded > 0)
    std::fprintf(out,
                 "warning: the shape's creases could not be meshed along (%s): meshed as a smooth surface, "
                 "its creases rounded; --creases exact refuses such a shape, --creases off meshes it smooth "
                 "without this warning\n",
                 w.crease_failure.c_str());
  if (w.creases_finer_edge > 0.0)
    std::fprintf(out,
                 "warning: the shape's creases could not be meshed along at the edge length asked for (%s): "
                 "meshed along them at edge length %.4g, about four times the vertices there; that "
                 "--edge-length asks for it directly\n",
                 w.crease_failure.c_str(), w.creases_finer_edge);
  if (w.creases_in_partition > 0)
    std::fprintf(
        out,
        "warning: the formula has creases, but the shape cut open by the region or seen through the frame "
        "(--region, --frame) could not be meshed along them: meshed through the partition as a smooth "
        "surface (creases rounded)\n");
  if (const auto& l = stats.local_sizes) {
    std::string where;
    if (l->sources > 0)
      where = std::to_string(l->sources) +
              " points where the box or region cuts f = 0 in features narrower than an edge";
    if (l->curvature_sources > 0)
      where += (where.empty() ? "" : " and ") + std::to_string(l->curvature_sources) +
               " points where f = 0 turns within an edge";
    if (l->around > 0)
      where += (where.empty() ? "" : " and ") + std::to_string(l->around) + " singular points";
    std::fprintf(
        out,
        "warning: sizes refined around %s, in %.4g,%.4g,%.4g,%.4g,%.4g,%.4g, down to %.3g: about %zu "
        "vertices added (--uniform keeps one size)\n",
        where.c_str(), l->extent.lo.x(), l->extent.lo.y(), l->extent.lo.z(), l->extent.hi.x(),
        l->extent.hi.y(), l->extent.hi.z(), l->smallest_size, l->added_vertices);
  }
  if (w.error_bound_violations.value_or(0) > 0)
    std::fprintf(out, "warning: %zu triangles have their centroid farther than --max-error from f = 0\n",
                 *w.error_bound_violations);
  // The clean-up removes every angle under 20 degrees it can; one under 10 is left only where the
  // surface turns within an edge (a rim narrower than the edges), or where cells left in doubt joined
  // sheets, which the warning above already names.
  if (doubtful == 0 && stats.cleanup && stats.cleanup->iterations > 0 && mesh.triangle_count() > 0) {
    const SmallAngleCount small = count_small_angles(mesh, 10.0);
    if (small.triangles > 0)
      std::fprintf(out,
                   "warning: %zu triangles have an angle under 10 degrees (smallest %.2g): the surface turns "
                   "within an edge there (a smaller --edge-length or --max-error resolves it)\n",
                   small.triangles, small.smallest);
  }
  if (const SelfIntersectionReport& r = crossings; r.pairs > 0)
    std::fprintf(
        out, "warning: the mesh intersects itself: %s%zu pairs of triangles (e.g. at %.6g, %.6g, %.6g)\n",
        r.capped ? "at least " : "", r.pairs, r.example_point.x(), r.example_point.y(), r.example_point.z());
}

}  // namespace isopatch::cli
