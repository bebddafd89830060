// MeshResult's Python methods (result.hpp). Arrays are copied out once per call; the Python wrapper
// (isopatch/_mesh.py) caches them.
#include "result.hpp"

#include <pybind11/stl.h>
#include <isopatch/curvature.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/render.hpp>
#include <isopatch/self_intersection.hpp>

#include "arrays.hpp"
#include "report_dict.hpp"
#include "run_released.hpp"

namespace py = pybind11;

namespace isopatch::python {

namespace {

py::array_t<double> double_array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

/// The mesh with the curvature and distance fields attached (a Python function's own distance).
Mesh mesh_with_fields(const MeshResult& r) {
  Mesh m = r.mesh;
  if (m.triangles.empty()) return m;
  attach_fields(m, *r.surface);
  if (r.distance) m.set_attribute("distance", std::vector<float>(r.distance->begin(), r.distance->end()));
  return m;
}

py::dict fields(const MeshResult& r) {
  py::dict d;
  if (r.mesh.triangles.empty()) return d;
  CurvatureFields f;
  {
    const py::gil_scoped_release release;
    f = curvature_fields(r.mesh, *r.surface);
  }
  d["mean_curvature"] = double_array(f.mean_discrete);
  d["mean_curvature_exact"] = double_array(f.mean_analytic);
  d["gaussian_curvature"] = double_array(f.gauss_discrete);
  d["gaussian_curvature_exact"] = double_array(f.gauss_analytic);
  d["distance"] = double_array(r.distance ? *r.distance : f.distance);
  for (const VertexAttribute& a : r.mesh.attributes)
    d[py::str(a.name)] = double_array(std::vector<double>(a.values.begin(), a.values.end()));
  return d;
}

py::dict stats(const MeshResult& r) {
  py::dict d;
  visit_stats(r.stats, [&d](std::string_view stage, std::string_view name, double value) {
    const py::str key{std::string(stage)};
    if (!d.contains(key)) d[key] = py::dict();
    py::dict of_stage = d[key];
    of_stage[py::str{std::string(name)}] = value;
  });
  if (!r.extra.empty()) {
    py::dict python;
    for (const auto& [name, value] : r.extra) python[py::str(name)] = value;
    d["python"] = python;
  }
  return d;
}

/// Written on a worker thread that Ctrl-C stops (run_released): KeyboardInterrupt, the temporary file
/// removed and a file already at `path` left as it was.
void write(const MeshResult& r, const std::string& path, bool with_fields) {
  const MeshFormat format = format_from_path(path);
  run_released([&](const std::atomic<bool>* cancel) {
    write_mesh(with_fields ? mesh_with_fields(r) : r.mesh, path, format, {}, cancel);
    return true;
  });
}

py::dict analyze(const MeshResult& r, bool against_surface) {
  QualityReport q;
  {
    const py::gil_scoped_release release;
    q = analyze_quality(r.mesh, against_surface ? r.surface.get() : nullptr);
  }
  return report_dict(q);
}

py::array_t<std::uint8_t> render(const MeshResult& r, int mode, const std::string& field,
                                 const std::vector<double>& values, int width, int height, double azimuth,
                                 double elevation, bool orthographic, std::optional<double> range,
                                 bool legend, const std::string& caption, const std::string& path) {
  RenderOptions o;
  o.mode = static_cast<RenderMode>(mode);
  o.field = field;
  o.values = values;
  o.width = width;
  o.height = height;
  o.azimuth = azimuth;
  o.elevation = elevation;
  o.camera = orthographic ? CameraKind::Orthographic : CameraKind::Perspective;
  o.range = range;
  o.legend = legend;
  o.caption = caption;
  Image image;
  {
    const py::gil_scoped_release release;
    const bool field_mode = o.mode == RenderMode::ScalarField || o.mode == RenderMode::Error;
    image = render_mesh(field_mode && values.empty() ? mesh_with_fields(r) : r.mesh, o);
    if (!path.empty()) write_png(image, path);
  }
  py::array_t<std::uint8_t> a(
      {static_cast<py::ssize_t>(image.height()), static_cast<py::ssize_t>(image.width()), py::ssize_t{3}});
  std::copy(image.bytes().begin(), image.bytes().end(), a.mutable_data());
  return a;
}

}  // namespace

void MeshResult::check_crossings() {
  const SelfIntersectionReport crossings = find_self_intersections(mesh);
  stats.warnings.self_intersecting_pairs = crossings.pairs;
  stats.warnings.self_intersection_near = crossings.example_point;
}

void MeshResult::normals_from_surface() {
  normals.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3 g = surface->value_gradient(mesh.positions[i]).gradient;
    const double n = g.norm();
    normals[i] = n > 0.0 ? Vec3(g / n) : Vec3::Zero();
  }
}

void bind_result(py::module_& m) {
  py::class_<MeshResult>(m, "MeshResult")
      .def("vertices", [](const MeshResult& r) { return vec3_array(r.mesh.positions); })
      .def("faces",
           [](const MeshResult& r) {
             py::array_t<std::int64_t> a({static_cast<py::ssize_t>(r.mesh.triangles.size()), py::ssize_t{3}});
             auto v = a.mutable_unchecked<2>();
             for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t)
               for (int c = 0; c < 3; ++c)
                 v(static_cast<py::ssize_t>(t), c) = r.mesh.triangles[t][static_cast<std::size_t>(c)];
             return a;
           })
      .def("normals", [](const MeshResult& r) { return vec3_array(r.normals); })
      .def("fields", &fields)
      .def("stats", &stats)
      .def("surface_name", [](const MeshResult& r) { return r.surface->name(); })
      .def("write", &write, py::arg("path"), py::arg("fields"))
      .def("analyze", &analyze, py::arg("against_surface"))
      .def("render", &render, py::arg("mode"), py::arg("field"), py::arg("values"), py::arg("width"),
           py::arg("height"), py::arg("azimuth"), py::arg("elevation"), py::arg("orthographic"),
           py::arg("range"), py::arg("legend"), py::arg("caption"), py::arg("path"));
}

}  // namespace isopatch::python
