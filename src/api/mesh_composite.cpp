// Meshing a composite surface (composite_mesh.hpp): projection with shared curve samples, or Marching
// Cubes on the piecewise function.
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/composite_settings.hpp"
#include "api/crease_meshing.hpp"
#include "api/multiresolution.hpp"
#include "api/task_arena_run.hpp"
#include "composite_mesher/composite_mesher.hpp"
#include "composite_mesher/composite_refinement.hpp"
#include "composite_mesher/patch_curvature.hpp"
#include "composite_model/budgeted_composite.hpp"
#include "composite_model/composite_surface.hpp"
#include "composite_model/ipatch_file.hpp"
#include "composite_model/patch_validity.hpp"
#include "refine/lattice_relaxation.hpp"

namespace isopatch {

void refuse_octree_settings(const Settings& settings) {
  const Settings defaults;
  const auto refuse = [](const char* field) {
    throw SettingError(field,
                       std::string(field) +
                           " shapes the octree, and a composite is meshed along its own curves: leave it "
                           "at its default, or give a region, a frame or cells to mesh the composite "
                           "through the partition");
  };
  if (settings.min_depth != defaults.min_depth) refuse("min_depth");
  if (settings.max_depth != defaults.max_depth) refuse("max_depth");
  if (settings.max_cell_curvature != defaults.max_cell_curvature) refuse("max_cell_curvature");
  if (!settings.refine_around.empty()) refuse("refine_around");
}

bool composite_refines(const Settings& settings) {
  return settings.refine > 1 ||
         (settings.refine == 0 && settings.remesh_iterations.value_or(1) > 0 && settings.resolution == 0);
}

bool meshed_through_partition(const Settings& settings) {
  return !settings.region.empty() || settings.frame.has_value() || !settings.cells.empty();
}

CompositeModel::CompositeModel(std::shared_ptr<const Composite> composite)
    : composite_(composite), surface_(std::make_shared<CompositeSurface>(std::move(composite))) {}

std::size_t CompositeModel::patch_count() const {
  return composite_->patches.size();
}

std::vector<std::string> CompositeModel::shape_warnings() const {
  std::vector<std::string> out;
  for (const PatchFinding& f : check_patch_validity(*composite_)) out.push_back(f.message);
  return out;
}

CompositeModel read_composite(const std::string& path) {
  return CompositeModel(std::make_shared<const Composite>(read_ipatch(path)));
}

CompositeModel parse_composite(std::string_view text, std::string_view source_name) {
  return CompositeModel(std::make_shared<const Composite>(parse_ipatch(text, source_name)));
}

bool is_composite_path(std::string_view path) {
  constexpr std::string_view kExtension = ".ipatch";
  return path.size() > kExtension.size() && path.substr(path.size() - kExtension.size()) == kExtension;
}

Mesh mesh_composite(const CompositeModel& model, const Settings& settings, MeshStats* stats) {
  settings.validate();
  // The construction's curves are not cut by region planes, nor is there a partition to rotate or
  // replace: with a region, a frame or given cells the composite is meshed as its piecewise function
  // through the partition, as a formula is (its seams then are not held as curves).
  if (settings.method == Method::MarchingCubes || meshed_through_partition(settings))
    return mesh_surface(*model.surface(), settings, stats);
  refuse_octree_settings(settings);
  return mesh_composite_along_curves(model, settings, stats);
}

Mesh mesh_composite_along_curves(const CompositeModel& model, const Settings& settings, MeshStats* stats,
                                 const std::function<void(Mesh&)>& finish) {
  return run_in_task_arena(settings, stats, [&] {
    std::optional<BudgetedComposite> budgeted;
    if (settings.max_evaluations > 0 || settings.time_limit > 0.0)
      budgeted.emplace(model.composite(), settings.max_evaluations, settings.time_limit);
    const Composite& c = budgeted ? budgeted->composite() : model.composite();
    // As for one surface (mesh_surface.cpp): the automatic level leaves the paper's method alone
    // (remesh_iterations = 0) unrefined, and so a fixed number of segments per curve (resolution).
    if (!composite_refines(settings)) return mesh_composite_projection(c, settings, stats).mesh;
    CompositeMesh last;  // the patches and curves of the last base (its mesh is the one returned)
    const auto one_level = [&](const Settings& s, MeshStats* st) {
      last = mesh_composite_projection(c, s, st);
      return std::exchange(last.mesh, Mesh{});
    };
    BaseRefinement bases;
    bases.keep_base_angles = true;
    bases.largest_curvature = [&](const Mesh& base) {
      return largest_patch_curvature(c, last.vertex_patch, base);
    };
    bases.refine = [&](const Mesh& base, const refine::RefineParams& params) {
      last.mesh = base;
      refine::RefineResult refined = refine_composite(c, last, params);
      last.mesh = Mesh{};
      if (finish && refined.failed_points == 0) {
        finish(refined.mesh);
        refined.smallest_angle = refine::smallest_angle_degrees(refined.mesh);
      }
      return refined;
    };
    return mesh_multiresolution(*model.surface(), settings, stats, one_level, nullptr, bases);
  });
}

}  // namespace isopatch
