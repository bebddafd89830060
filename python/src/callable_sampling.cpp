// Batched calls into a Python function: sampling and vertex projection (callable_sampling.hpp).
#include "callable_sampling.hpp"

#include <pybind11/numpy.h>
#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace py = pybind11;

namespace isopatch::python {

namespace {

std::string point_text(const Vec3& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

/// An (n, 3) float64 array of points[first .. first + n).
py::array_t<double> point_array(const std::vector<Vec3>& points, std::size_t first, std::size_t n) {
  py::array_t<double> a({static_cast<py::ssize_t>(n), py::ssize_t{3}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) m(static_cast<py::ssize_t>(i), c) = points[first + i][c];
  return a;
}

/// The callable's result as `rows` x `columns` doubles (columns 1: a vector of n values).
py::array_t<double> checked_result(const py::object& result, std::size_t rows, int columns,
                                   const char* what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(result);
  if (!a) throw InputError(std::string(what) + " must return a numeric array");
  const bool ok =
      columns == 1 ? (a.ndim() == 1 && static_cast<std::size_t>(a.shape(0)) == rows) ||
                         (a.ndim() == 2 && static_cast<std::size_t>(a.shape(0)) == rows && a.shape(1) == 1)
                   : a.ndim() == 2 && static_cast<std::size_t>(a.shape(0)) == rows && a.shape(1) == columns;
  if (!ok) {
    std::string shape;
    for (py::ssize_t d = 0; d < a.ndim(); ++d) {
      if (d) shape.append(", ");
      shape.append(std::to_string(a.shape(d)));
    }
    throw InputError(std::string(what) + " returned an array of shape (" + shape + ") for " +
                     std::to_string(rows) + " points; want (" + std::to_string(rows) +
                     (columns == 1 ? ",)" : ", 3)"));
  }
  return a;
}

}  // namespace

std::vector<double> BatchFunction::values(const std::vector<Vec3>& pts) {
  std::vector<double> out(pts.size());
  for (std::size_t first = 0; first < pts.size(); first += batch) {
    const std::size_t n = std::min(batch, pts.size() - first);
    const py::array_t<double> a = checked_result(value(point_array(pts, first, n)), n, 1, "the function");
    ++calls;
    points += n;
    const double* v = a.data();
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(v[i]))
        throw EvaluationError("f is " + std::string(std::isnan(v[i]) ? "NaN" : "infinite") + " at " +
                              point_text(pts[first + i]));
      out[first + i] = v[i];
    }
  }
  return out;
}

void BatchFunction::values_gradients(const std::vector<Vec3>& pts, double h, std::vector<double>& f,
                                     std::vector<Vec3>& g) {
  g.assign(pts.size(), Vec3::Zero());
  if (!gradient.is_none()) {
    f = values(pts);
    for (std::size_t first = 0; first < pts.size(); first += batch) {
      const std::size_t n = std::min(batch, pts.size() - first);
      const py::array_t<double> a =
          checked_result(gradient(point_array(pts, first, n)), n, 3, "the gradient function");
      ++calls;
      points += n;
      const double* v = a.data();
      for (std::size_t i = 0; i < n; ++i) g[first + i] = Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    }
    return;
  }
  // Central differences: each point followed by its six neighbours at +-h along x, y, z.
  std::vector<Vec3> stencil;
  stencil.reserve(pts.size() * 7);
  for (const Vec3& p : pts) {
    stencil.push_back(p);
    for (int a = 0; a < 3; ++a)
      for (const double s : {h, -h}) {
        Vec3 q = p;
        q[a] += s;
        stencil.push_back(q);
      }
  }
  const std::vector<double> v = values(stencil);
  f.resize(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    f[i] = v[7 * i];
    for (int a = 0; a < 3; ++a) g[i][a] = (v[7 * i + 1 + 2 * a] - v[7 * i + 2 + 2 * a]) / (2.0 * h);
  }
}

Volume sample_on_grid(BatchFunction& f, const Box& box, int cells) {
  const double step = box.size().maxCoeff() / cells;
  Volume v;
  v.origin = box.lo;
  for (int a = 0; a < 3; ++a) {
    const auto n = static_cast<std::size_t>(std::max(3.0, std::ceil(box.size()[a] / step - 1e-9))) + 1;
    v.shape[static_cast<std::size_t>(a)] = n;
    v.spacing[a] = box.size()[a] / static_cast<double>(n - 1);
  }
  std::vector<Vec3> points;
  points.reserve(v.shape[0] * v.shape[1] * v.shape[2]);
  for (std::size_t i = 0; i < v.shape[0]; ++i)
    for (std::size_t j = 0; j < v.shape[1]; ++j)
      for (std::size_t k = 0; k < v.shape[2]; ++k) {
        const Vec3 index(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k));
        Vec3 p = v.origin + v.spacing.cwiseProduct(index);
        // The last sample of each axis is the box's own bound, not a rounded sum.
        if (i + 1 == v.shape[0]) p.x() = box.hi.x();
        if (j + 1 == v.shape[1]) p.y() = box.hi.y();
        if (k + 1 == v.shape[2]) p.z() = box.hi.z();
        points.push_back(p);
      }
  v.samples = f.values(points);
  return v;
}

ProjectionOutcome project_vertices(BatchFunction& f, Mesh& mesh, const Box& box, double max_step,
                                   std::vector<Vec3>& normals, std::vector<double>& distance) {
  const double diagonal = box.diagonal();
  const double tolerance = 1e-12 * diagonal;
  const double h = 6e-6 * diagonal;  // about cbrt(machine epsilon) of the box: central differences
  const double face_tolerance = 1e-9 * diagonal;
  ProjectionOutcome outcome;
  std::vector<std::size_t> active(mesh.positions.size());
  for (std::size_t i = 0; i < active.size(); ++i) active[i] = i;
  std::vector<double> fv;
  std::vector<Vec3> gv;
  for (int step = 0; step < 8 && !active.empty(); ++step) {
    std::vector<Vec3> points;
    points.reserve(active.size());
    for (const std::size_t i : active) points.push_back(mesh.positions[i]);
    f.values_gradients(points, h, fv, gv);
    ++outcome.steps;
    std::vector<std::size_t> still;
    for (std::size_t n = 0; n < active.size(); ++n) {
      Vec3& p = mesh.positions[active[n]];
      Vec3 g = gv[n];
      for (int a = 0; a < 3; ++a)  // on a face of the box: stay in it
        if (std::abs(p[a] - box.lo[a]) <= face_tolerance || std::abs(p[a] - box.hi[a]) <= face_tolerance)
          g[a] = 0.0;
      const double g2 = g.squaredNorm();
      const Vec3 move = -fv[n] / g2 * g;
      if (!(g2 > 0.0) || !std::isfinite(g2) || !(move.norm() <= max_step)) {
        ++outcome.unprojected;  // no usable step: the vertex stays on the interpolant's surface
        continue;
      }
      if (move.norm() <= tolerance) continue;
      p += move;
      still.push_back(active[n]);
    }
    active.swap(still);
  }
  outcome.unprojected += active.size();
  // The final values and gradients for normals and distances.
  f.values_gradients(mesh.positions, h, fv, gv);
  normals.resize(mesh.positions.size());
  distance.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const double norm = gv[i].norm();
    normals[i] = norm > 0.0 ? Vec3(gv[i] / norm) : Vec3::Zero();
    distance[i] = norm > 0.0 ? fv[i] / norm : std::numeric_limits<double>::quiet_NaN();
  }
  return outcome;
}

}  // namespace isopatch::python
