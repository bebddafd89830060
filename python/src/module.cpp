// isopatch._isopatch: the compiled half of the Python package (the other half, isopatch/*.py, gives
// the documented API). Every long call runs without the GIL (run_released.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <isopatch/composite_mesh.hpp>
#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/vdb_surface.hpp>
#include <isopatch/version.hpp>
#include <isopatch/volume_io.hpp>
#include <isopatch/volume_surface.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "blocks.hpp"
#include "callable_sampling.hpp"
#include "errors.hpp"
#include "result.hpp"
#include "run_released.hpp"
#include "settings_args.hpp"
#include "tiles.hpp"

namespace py = pybind11;

namespace isopatch::python {

namespace {

/// Meshes `surface` without the GIL (Ctrl-C cancels) and fills normals from it.
MeshResult mesh_released(SurfacePtr surface, Settings settings) {
  MeshResult r;
  r.surface = std::move(surface);
  return run_released([&](const std::atomic<bool>* cancel) {
    settings.cancel = cancel;
    r.mesh = mesh_surface(*r.surface, settings, &r.stats);
    r.check_crossings();
    r.normals_from_surface();
    return std::move(r);
  });
}

/// A composite (.ipatch) read without the GIL. \throw InputError when it is given params.
CompositeModel read_composite_released(const std::string& path, const std::map<std::string, double>& params) {
  if (!params.empty())
    throw InputError("params are for formulas, not composite surfaces (.ipatch)", "params");
  return run_released([&](const std::atomic<bool>*) { return read_composite(path); });
}

/// The surface a spec names: a composite's piecewise function for a .ipatch file, else
/// resolve_surface().
SurfacePtr spec_surface(const std::string& spec, const std::optional<Box>& box,
                        const std::map<std::string, double>& params) {
  if (is_composite_path(spec)) return read_composite_released(spec, params).surface();
  return resolve_surface(spec, box, params);
}

MeshResult mesh_spec(const std::string& spec, const BoxArg& box, const std::map<std::string, double>& params,
                     const py::dict& options) {
  Settings settings = to_settings(options);
  settings.box = to_box(box);
  if (is_composite_path(spec)) {  // its patches meshed along its curves, as the command line does
    const CompositeModel model = read_composite_released(spec, params);
    MeshResult r;
    r.surface = model.surface();
    return run_released([&](const std::atomic<bool>* cancel) {
      settings.cancel = cancel;
      r.mesh = mesh_composite(model, settings, &r.stats);
      r.check_crossings();
      r.normals_from_surface();
      return std::move(r);
    });
  }
  SurfacePtr surface = resolve_surface_in_region(spec, settings.box, settings.region, params);
  return mesh_released(std::move(surface), std::move(settings));
}

MeshResult mesh_callable(const py::object& f, const py::object& gradient, const BoxArg& box_arg,
                         std::optional<int> samples, std::size_t batch, const py::dict& options) {
  Settings settings = to_settings(options);
  const std::optional<Box> box = to_box(box_arg);
  if (!box) throw InputError("a Python function needs a box", "box");
  settings.box = box;
  settings.validate();
  // Samples: two per target edge along the longest side, 64..256 cells (1.5 per edge with max_error,
  // whose smallest edges are finer still, so the interpolant is sampled at the cap then).
  const double edge = default_edge_length(settings, *box);
  const int cells = samples.value_or(
      static_cast<int>(std::clamp(std::ceil(2.0 * box->size().maxCoeff() / edge), 64.0, 256.0)));
  if (cells < 4 || cells > 1024) throw InputError("samples must be in 4..1024", "samples");
  if (batch < 1) throw InputError("batch must be at least 1", "batch");
  BatchFunction fn{f, gradient, batch};
  Volume volume = sample_on_grid(fn, *box, cells);
  const Vec3 spacing = volume.spacing;
  SurfacePtr surface;
  try {
    surface = volume_surface(std::move(volume), 0.0, "python function");
  } catch (const NoSurfaceError&) {
    throw NoSurfaceError("f does not change sign at the " + std::to_string(cells) +
                         " samples along the box's longest side (raise samples=, or check the box)");
  }
  const std::size_t sampling_calls = fn.calls;
  MeshResult r = mesh_released(std::move(surface), std::move(settings));
  std::vector<double> distance;
  const ProjectionOutcome p =
      project_vertices(fn, r.mesh, *box, 0.5 * spacing.minCoeff(), r.normals, distance);
  r.distance = std::move(distance);
  r.extra = {{"calls", static_cast<double>(fn.calls)},
             {"sampling_calls", static_cast<double>(sampling_calls)},
             {"points", static_cast<double>(fn.points)},
             {"sample_cells", static_cast<double>(cells)},
             {"newton_steps", p.steps},
             {"unprojected_vertices", static_cast<double>(p.unprojected)}};
  return r;
}

Volume to_volume(const py::array_t<double, py::array::c_style | py::array::forcecast>& array,
                 const std::array<double, 3>& spacing, const std::array<double, 3>& origin) {
  if (array.ndim() != 3)
    throw InputError(
        "the volume must be a 3-dimensional array, not " + std::to_string(array.ndim()) + "-dimensional",
        "volume");
  Volume v;
  for (int a = 0; a < 3; ++a) {
    v.shape[static_cast<std::size_t>(a)] = static_cast<std::size_t>(array.shape(a));
    v.spacing[a] = spacing[static_cast<std::size_t>(a)];
    v.origin[a] = origin[static_cast<std::size_t>(a)];
  }
  v.samples.assign(array.data(), array.data() + array.size());
  return v;
}

MeshResult mesh_volume(const py::array_t<double, py::array::c_style | py::array::forcecast>& array,
                       double level, const std::array<double, 3>& spacing,
                       const std::array<double, 3>& origin, const BoxArg& box, const py::dict& options) {
  Settings settings = to_settings(options);
  settings.box = to_box(box);
  Volume volume = to_volume(array, spacing, origin);
  SurfacePtr surface =
      run_released([&](const std::atomic<bool>*) { return volume_surface(std::move(volume), level); });
  return mesh_released(std::move(surface), std::move(settings));
}

MeshResult mesh_vdb(const std::string& path, const std::string& grid, double level, bool inside_above,
                    const BoxArg& box, const py::dict& options) {
  Settings settings = to_settings(options);
  settings.box = to_box(box);
  SurfacePtr surface = run_released([&](const std::atomic<bool>*) {
    return vdb_surface(path, VdbSource{grid, level, inside_above});
  });
  return mesh_released(std::move(surface), std::move(settings));
}

py::list vdb_grid_list(const std::string& path) {
  const std::vector<VdbGridInfo> grids =
      run_released([&](const std::atomic<bool>*) { return vdb_grids(path); });
  py::list out;
  for (const VdbGridInfo& g : grids) {
    py::dict d;
    d["name"] = g.name;
    d["value_type"] = g.value_type;
    d["grid_class"] = g.grid_class;
    d["active_voxels"] = g.active_voxels;
    out.append(d);
  }
  return out;
}

MeshResult mesh_from_arrays(const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
                            const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& faces,
                            const std::string& spec, const BoxArg& box) {
  if (vertices.ndim() != 2 || vertices.shape(1) != 3)
    throw InputError("vertices must be an (V, 3) array", "vertices");
  if (faces.ndim() != 2 || faces.shape(1) != 3) throw InputError("faces must be an (F, 3) array", "faces");
  MeshResult r;
  const double* v = vertices.data();
  for (py::ssize_t i = 0; i < vertices.shape(0); ++i)
    r.mesh.positions.emplace_back(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  const std::int64_t* f = faces.data();
  const auto count = static_cast<std::int64_t>(r.mesh.positions.size());
  for (py::ssize_t t = 0; t < faces.shape(0); ++t) {
    Triangle tri;
    for (int c = 0; c < 3; ++c) {
      const std::int64_t index = f[3 * t + c];
      if (index < 0 || index >= count)
        throw InputError("face " + std::to_string(t) + " refers to vertex " + std::to_string(index) +
                             " but there are " + std::to_string(count) + " vertices",
                         "faces");
      tri[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(index);
    }
    r.mesh.triangles.push_back(tri);
  }
  r.mesh.validate();
  r.surface = spec_surface(spec, to_box(box), {});
  r.normals_from_surface();
  return r;
}

py::tuple read_volume_file(const std::string& path) {
  Volume v = run_released([&](const std::atomic<bool>*) { return read_volume(path); });
  py::array_t<double> a({static_cast<py::ssize_t>(v.shape[0]), static_cast<py::ssize_t>(v.shape[1]),
                         static_cast<py::ssize_t>(v.shape[2])});
  std::copy(v.samples.begin(), v.samples.end(), a.mutable_data());
  return py::make_tuple(a, py::make_tuple(v.spacing.x(), v.spacing.y(), v.spacing.z()),
                        py::make_tuple(v.origin.x(), v.origin.y(), v.origin.z()));
}

}  // namespace

}  // namespace isopatch::python

PYBIND11_MODULE(_isopatch, m) {
  using namespace isopatch::python;
  m.doc() = "The compiled part of isopatch; use the functions of the isopatch package instead.";
  // The library's version (project() in the top CMakeLists.txt); the package re-exports it.
  m.attr("__version__") = std::string(isopatch::kVersion);
  register_error_translator();
  bind_result(m);
  bind_blocks(m);
  bind_tiles(m);
  m.def("mesh_spec", &mesh_spec, py::arg("spec"), py::arg("box"), py::arg("params"), py::arg("options"));
  m.def("mesh_callable", &mesh_callable, py::arg("f"), py::arg("gradient"), py::arg("box"),
        py::arg("samples"), py::arg("batch"), py::arg("options"));
  m.def("mesh_volume", &mesh_volume, py::arg("volume"), py::arg("level"), py::arg("spacing"),
        py::arg("origin"), py::arg("box"), py::arg("options"));
  m.def("read_volume", &read_volume_file, py::arg("path"));
  m.def("mesh_vdb", &mesh_vdb, py::arg("path"), py::arg("grid"), py::arg("level"), py::arg("inside_above"),
        py::arg("box"), py::arg("options"));
  m.def("vdb_grids", &vdb_grid_list, py::arg("path"));
  m.def("mesh_from_arrays", &mesh_from_arrays, py::arg("vertices"), py::arg("faces"), py::arg("spec"),
        py::arg("box"));
  m.def("catalogue", [] {
    py::list names;
    for (const auto& entry : isopatch::catalogue()) names.append(std::string(entry.name));
    return names;
  });
}
