// Box and settings arguments of the bindings (settings_args.hpp).
#include "settings_args.hpp"

#include <pybind11/stl.h>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>

#include <string>

namespace py = pybind11;

namespace isopatch::python {
namespace {

/// Sets the Settings field of that name. \throw py::cast_error for a value of the wrong type.
void set_option(Settings& s, const std::string& key, const py::handle& value) {
  if (key == "method")
    s.method = parse_method(value.cast<std::string>());
  else if (key == "edge_length")
    s.edge_length = value.cast<double>();
  else if (key == "max_error")
    s.max_error = value.cast<double>();
  else if (key == "quality")
    s.quality = parse_quality(value.cast<std::string>());
  else if (key == "threads")
    s.threads = value.cast<int>();
  else if (key == "remesh")
    s.remesh_iterations = value.cast<int>();
  else if (key == "refine")
    s.refine = value.cast<int>();
  else if (key == "resolution")
    s.resolution = value.cast<int>();
  else if (key == "grid")
    s.grid = value.cast<int>();
  else if (key == "max_vertices")
    s.max_vertices = value.cast<std::size_t>();
  else if (key == "max_evaluations")
    s.max_evaluations = value.cast<std::uint64_t>();
  else if (key == "time_limit")
    s.time_limit = value.cast<double>();
  else if (key == "uniform")
    s.uniform = value.cast<bool>();
  else if (key == "creases")
    s.creases = parse_creases(value.cast<std::string>());
  else
    throw InputError("unknown setting '" + key + "'", key);
}

}  // namespace

std::optional<Box> to_box(const BoxArg& arg) {
  if (!arg) return std::nullopt;
  Box b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = arg->first[static_cast<std::size_t>(a)];
    b.hi[a] = arg->second[static_cast<std::size_t>(a)];
  }
  return valid_box(b);
}

/// Settings from the keyword arguments the Python wrapper passes (only those not None).
Settings to_settings(const py::dict& options) {
  Settings s;
  for (const auto& [key_handle, value] : options) {
    const auto key = key_handle.cast<std::string>();
    try {
      set_option(s, key, value);
    } catch (const py::cast_error&) {
      throw SettingError(key, key + " has the wrong type (" +
                                  py::str(value.get_type().attr("__name__")).cast<std::string>() + ")");
    }
  }
  return s;
}

}  // namespace isopatch::python
