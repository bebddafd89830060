// Box and settings arguments of the bindings (settings_args.hpp).
#include "settings_args.hpp"

#include <pybind11/stl.h>
#include <isopatch/convex_region.hpp>
#include <isopatch/error.hpp>
#include <isopatch/isopatch.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace py = pybind11;

namespace isopatch::python {
namespace {

/// A region as the command line's --region text ("a,b,c,d;...") or a sequence of (a, b, c, d) planes,
/// each the half-space a x + b y + c z + d <= 0. \throw InputError as parse_region().
ConvexRegion to_region(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return parse_region(value.cast<std::string>());
  ConvexRegion region;
  for (const auto& plane : value.cast<std::vector<std::array<double, 4>>>())
    region.push_back({plane[0], plane[1], plane[2], plane[3]});
  validate_region(region, "region");
  return region;
}

/// A frame as the command line's --frame text ("AZ,EL,ROLL") or a sequence of three angles in degrees.
/// \throw InputError as parse_frame() (three finite numbers).
Frame to_frame(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return parse_frame(value.cast<std::string>());
  const auto angles = value.cast<std::array<double, 3>>();
  for (const double a : angles)
    if (!std::isfinite(a)) throw InputError("the frame's angles must be finite numbers of degrees", "frame");
  Frame frame;
  frame.azimuth = angles[0];
  frame.elevation = angles[1];
  frame.roll = angles[2];
  return frame;
}

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
  else if (key == "region")
    s.region = to_region(value);
  else if (key == "frame")
    s.frame = to_frame(value);
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
