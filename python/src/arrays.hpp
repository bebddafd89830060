#pragma once
// NumPy arrays made from the library's vectors, shared by the bindings.

#include <pybind11/numpy.h>
#include <isopatch/geometry.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace isopatch::python {

/// Arrays the bindings take: float64 points and uint32 indices, C order (converted when not).
using Positions = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;
using Indices = pybind11::array_t<std::uint32_t, pybind11::array::c_style | pybind11::array::forcecast>;

/// A one-dimensional array of `v`'s values, copied.
template <typename T>
pybind11::array_t<T> vector_array(const std::vector<T>& v) {
  return pybind11::array_t<T>(static_cast<pybind11::ssize_t>(v.size()), v.data());
}

/// `flat` as an (N, width) array, copied.
template <typename T>
pybind11::array_t<T> rows(const std::vector<T>& flat, std::size_t width) {
  pybind11::array_t<T> out(
      {static_cast<pybind11::ssize_t>(flat.size() / width), static_cast<pybind11::ssize_t>(width)});
  std::copy(flat.begin(), flat.end(), out.mutable_data());
  return out;
}

/// An (N, 3) array of triangles' vertex numbers (Mesh::triangles, BlockMesh::triangles), copied.
template <typename T>
pybind11::array_t<T> triangle_array(const std::vector<std::array<T, 3>>& triangles) {
  pybind11::array_t<T> out({static_cast<pybind11::ssize_t>(triangles.size()), pybind11::ssize_t{3}});
  T* to = out.mutable_data();
  for (const auto& t : triangles) to = std::copy(t.begin(), t.end(), to);
  return out;
}

/// An (N, 3) float64 array of `v`'s points, copied.
inline pybind11::array_t<double> vec3_array(const std::vector<Vec3>& v) {
  pybind11::array_t<double> a({static_cast<pybind11::ssize_t>(v.size()), pybind11::ssize_t{3}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int c = 0; c < 3; ++c) m(static_cast<pybind11::ssize_t>(i), c) = v[i][c];
  return a;
}

/// Puts a refined block's or tile's guard and quality figures into `out`: failed_points, smallest_angle,
/// kept, seam_band_vertices.
template <typename Refined>
void put_refinement_figures(pybind11::dict& out, const Refined& refined) {
  out["failed_points"] = refined.failed_points;
  out["smallest_angle"] = refined.smallest_angle;
  out["kept"] = refined.kept;
  out["seam_band_vertices"] = refined.seam_band_vertices;
}

}  // namespace isopatch::python
