#pragma once
// NumPy arrays made from the library's vectors, shared by the bindings.

#include <pybind11/numpy.h>
#include <isopatch/geometry.hpp>

#include <vector>

namespace isopatch::python {

/// An (N, 3) float64 array of `v`'s points, copied.
inline pybind11::array_t<double> vec3_array(const std::vector<Vec3>& v) {
  pybind11::array_t<double> a({static_cast<pybind11::ssize_t>(v.size()), pybind11::ssize_t{3}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int c = 0; c < 3; ++c) m(static_cast<pybind11::ssize_t>(i), c) = v[i][c];
  return a;
}

}  // namespace isopatch::python
