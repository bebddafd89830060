// Tiles by planes for isopatch.distributed (tiles.hpp): the plan, one face's curves and one tile's
// mesh, as NumPy arrays a task can write to a file and read back.
#include "tiles.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <isopatch/blocks.hpp>
#include <isopatch/error.hpp>
#include <isopatch/tiles.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "run_released.hpp"
#include "settings_args.hpp"
#include "surface_source.hpp"

namespace py = pybind11;

namespace isopatch::python {
namespace {

py::object item(const py::dict& d, const char* key, const char* what) {
  if (!d.contains(key)) throw InputError(std::string(what) + " has no '" + key + "'", what);
  return d[key];
}

/// A plan as a dict (plan_dict()) read back. \throw InputError when it is not one.
TilePlan to_plan(const py::dict& d) {
  TilePlan plan;
  plan.level = item(d, "level", "plan").cast<int>();
  plan.edge = item(d, "edge", "plan").cast<double>();
  const auto counts = item(d, "counts", "plan").cast<std::array<int, 3>>();
  const auto planes = item(d, "planes", "plan").cast<std::array<std::vector<double>, 3>>();
  for (int a = 0; a < 3; ++a) {
    const auto& list = planes[static_cast<std::size_t>(a)];
    if (counts[static_cast<std::size_t>(a)] < 1 ||
        list.size() != static_cast<std::size_t>(counts[static_cast<std::size_t>(a)]) + 1)
      throw InputError("the plan's planes do not fit its counts", "plan");
    for (std::size_t i = 0; i + 1 < list.size(); ++i)
      if (!(std::isfinite(list[i]) && list[i] < list[i + 1] && std::isfinite(list[i + 1])))
        throw InputError("the plan's planes must rise and be finite", "plan");
  }
  if (plan.level < 1 || plan.level > 32 || !(plan.edge > 0.0) || !std::isfinite(plan.edge))
    throw InputError("the plan's level or edge is out of range", "plan");
  const Box domain{Vec3(planes[0].front(), planes[1].front(), planes[2].front()),
                   Vec3(planes[0].back(), planes[1].back(), planes[2].back())};
  plan.grid = make_tile_grid(domain, counts);
  plan.grid.planes = planes;
  return plan;
}

py::dict plan_dict(const TilePlan& plan) {
  py::dict out;
  out["level"] = plan.level;
  out["edge"] = plan.edge;
  out["counts"] = plan.grid.counts;
  py::list planes;
  for (const auto& list : plan.grid.planes) planes.append(vector_array(list));
  out["planes"] = planes;
  out["estimated_vertices"] = plan.estimated_vertices;
  out["faces"] = grid_faces(plan.grid).size();
  return out;
}

py::dict curves_dict(const FaceCurves& c) {
  std::vector<std::uint32_t> indices;
  std::vector<std::int64_t> offsets{0};
  for (const auto& curve : c.curves) {
    indices.insert(indices.end(), curve.begin(), curve.end());
    offsets.push_back(static_cast<std::int64_t>(indices.size()));
  }
  py::dict out;
  out["face"] = std::array<int, 4>{c.face.axis, c.face.index, c.face.cell[0], c.face.cell[1]};
  out["spacing"] = c.spacing;
  out["points"] = vec3_array(c.points);
  out["offsets"] = vector_array(offsets);
  out["indices"] = vector_array(indices);
  return out;
}

FaceCurves to_curves(const py::dict& d) {
  FaceCurves c;
  const auto face = item(d, "face", "face").cast<std::array<int, 4>>();
  c.face = {face[0], face[1], {face[2], face[3]}};
  c.spacing = item(d, "spacing", "face").cast<double>();
  const auto points = item(d, "points", "face").cast<Positions>();
  if (points.ndim() != 2 || points.shape(1) != 3) throw InputError("a face's points must be (N, 3)", "face");
  for (py::ssize_t i = 0; i < points.shape(0); ++i)
    c.points.emplace_back(points.at(i, 0), points.at(i, 1), points.at(i, 2));
  const auto offsets =
      item(d, "offsets", "face").cast<py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>>();
  const auto indices = item(d, "indices", "face").cast<Indices>();
  if (offsets.size() < 1 || offsets.data()[0] != 0 || offsets.data()[offsets.size() - 1] != indices.size())
    throw InputError("a face's curve offsets do not fit its indices", "face");
  for (py::ssize_t k = 0; k + 1 < offsets.size(); ++k) {
    const std::int64_t begin = offsets.data()[k], end = offsets.data()[k + 1];
    if (begin > end) throw InputError("a face's curve offsets do not rise", "face");
    std::vector<std::uint32_t> curve(indices.data() + begin, indices.data() + end);
    for (const std::uint32_t p : curve)
      if (p >= c.points.size()) throw InputError("a face's curve names a point it does not have", "face");
    c.curves.push_back(std::move(curve));
  }
  return c;
}

/// A tiled job as a process holds it: the source and box, the surface made on first use.
class TileJob {
 public:
  TileJob(const py::dict& source, const BoxArg& box) : source_(source), box_(to_box(box)) {
    if (source_.composite())
      throw SettingError("tiles",
                         "a composite (.ipatch) is meshed in blocks of its base, not in tiles by planes");
  }

  py::dict plan(const py::dict& options, int tiles) {
    Settings settings = settings_of(options);
    const TilePlan plan = run_released([&](const std::atomic<bool>* cancel) {
      settings.cancel = cancel;
      const SurfacePtr f = surface();
      if (source_.volume.empty() && capped_pieces(*f, settings))
        throw SettingError("split",
                           "a lattice capped by planes is meshed in blocks of its cut surfaces, closed by "
                           "its caps (--split blocks), not in tiles by planes");
      if (source_.volume.empty() && creased_pieces(*f, settings))
        throw SettingError("creases",
                           "a formula with exact creases is meshed in blocks of its base (or with "
                           "creases off), not in tiles by planes");
      return plan_tiles(*f, settings, tiles);
    });
    return plan_dict(plan);
  }

  py::dict face(const py::dict& options, const py::dict& plan_arrays, int number) {
    const TilePlan plan = to_plan(plan_arrays);
    const auto faces = grid_faces(plan.grid);
    if (number < 0 || static_cast<std::size_t>(number) >= faces.size())
      throw InputError("face " + std::to_string(number) + " is not a face of the plan", "face");
    (void)settings_of(options);
    const FaceCurves curves = run_released([&](const std::atomic<bool>*) {
      return face_curves(*surface(), plan.grid, faces[static_cast<std::size_t>(number)], plan.spacing());
    });
    return curves_dict(curves);
  }

  py::dict tile(const py::dict& options, const py::dict& plan_arrays, int number, const py::list& face_list) {
    const TilePlan plan = to_plan(plan_arrays);
    if (number < 0 || number >= plan.grid.tile_count())
      throw InputError("tile " + std::to_string(number) + " is not a tile of the plan", "tile");
    std::vector<FaceCurves> faces;
    for (const auto& f : face_list) faces.push_back(to_curves(f.cast<py::dict>()));
    Settings settings = settings_of(options);
    TileMesh mesh = run_released([&](const std::atomic<bool>* cancel) {
      settings.cancel = cancel;
      return mesh_tile(*surface(), settings, plan, plan.grid.tile(number), faces);
    });
    py::dict out;
    out["positions"] = vec3_array(mesh.mesh.positions);
    out["triangles"] = triangle_array(mesh.mesh.triangles);
    out["boundary"] = vector_array(mesh.cut);
    put_refinement_figures(out, mesh);
    return out;
  }

 private:
  Source source_;
  std::optional<Box> box_;
  std::mutex mutex_;
  SurfacePtr surface_;

  Settings settings_of(const py::dict& options) const {
    Settings settings = to_settings(options);
    settings.box = box_;
    return settings;
  }

  SurfacePtr surface() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!surface_) surface_ = source_.surface(box_);
    return surface_;
  }
};

}  // namespace

void bind_tiles(py::module_& m) {
  py::class_<TileJob>(m, "TileJob")
      .def(py::init<const py::dict&, const BoxArg&>(), py::arg("source"), py::arg("box"))
      .def("plan", &TileJob::plan, py::arg("options"), py::arg("tiles"))
      .def("face", &TileJob::face, py::arg("options"), py::arg("plan"), py::arg("face"))
      .def("tile", &TileJob::tile, py::arg("options"), py::arg("plan"), py::arg("tile"), py::arg("faces"));
}

}  // namespace isopatch::python
