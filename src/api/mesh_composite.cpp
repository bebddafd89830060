// Meshing a composite surface (composite_mesh.hpp): projection with shared curve samples, or Marching
// Cubes on the piecewise function.
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <optional>

#include "api/budgeted_composite.hpp"
#include "composite/composite_mesher.hpp"
#include "ipatch/composite_surface.hpp"
#include "ipatch/ipatch_file.hpp"
#include "ipatch/patch_validity.hpp"

namespace isopatch {

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
  if (settings.method == Method::MarchingCubes) return mesh_surface(*model.surface(), settings, stats);
  const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
  if (stats) stats->threads = threads;
  tbb::task_arena arena(threads);
  return arena.execute([&] {
    std::optional<BudgetedComposite> budgeted;
    if (settings.max_evaluations > 0 || settings.time_limit > 0.0)
      budgeted.emplace(model.composite(), settings.max_evaluations, settings.time_limit);
    const Composite& c = budgeted ? budgeted->composite() : model.composite();
    return mesh_composite_projection(c, settings, stats).mesh;
  });
}

}  // namespace isopatch
