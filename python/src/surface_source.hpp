#pragma once
// A surface named by a source dict, the same on the driver and on every worker of a distributed run
// (isopatch.distributed): {"spec": formula, catalogue name, @file or a composite's .ipatch file,
// "params": {...}} or {"volume": path of a .npy or .nrrd file, "level": value}, with "coefficients" (a
// .npy of its B-spline coefficients made by the distributed prefilter, mapped instead of the volume
// read), "spacing" and "origin" when a distributed run made them.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/volume_io.hpp>
#include <isopatch/volume_surface.hpp>

#include <array>
#include <map>
#include <optional>
#include <string>

namespace isopatch::python {

namespace py = pybind11;

/// A surface as a source dict names it, read while holding the GIL so that it can be resolved without.
struct Source {
  std::string spec, volume, coefficients;
  std::map<std::string, double> params;
  double level = 0.0;
  Vec3 spacing = Vec3::Ones(), origin = Vec3::Zero();

  explicit Source(const py::dict& source) {
    if (source.contains("volume")) {
      volume = source["volume"].cast<std::string>();
      if (source.contains("level")) level = source["level"].cast<double>();
      if (source.contains("coefficients")) {
        coefficients = source["coefficients"].cast<std::string>();
        const auto s = source["spacing"].cast<std::array<double, 3>>();
        const auto o = source["origin"].cast<std::array<double, 3>>();
        spacing = Vec3(s[0], s[1], s[2]);
        origin = Vec3(o[0], o[1], o[2]);
      }
      return;
    }
    if (!source.contains("spec")) throw InputError("a source names a 'spec' or a 'volume'", "source");
    spec = source["spec"].cast<std::string>();
    if (source.contains("params")) params = source["params"].cast<std::map<std::string, double>>();
  }

  bool composite() const { return volume.empty() && is_composite_path(spec); }

  /// The composite a .ipatch spec names (read). Needs no GIL. \throw InputError when it has params.
  CompositeModel read_model() const {
    if (!params.empty())
      throw InputError("params are for formulas, not composite surfaces (.ipatch)", "params");
    return read_composite(spec);
  }

  /// The surface (the coefficients mapped, the volume read and prefiltered, or the formula compiled).
  /// Needs no GIL.
  SurfacePtr surface(const std::optional<Box>& box) const {
    if (!coefficients.empty()) return mapped_volume_surface(coefficients, spacing, origin, level, volume);
    if (!volume.empty()) return volume_surface(read_volume(volume), level, volume);
    return resolve_surface(spec, box, params);
  }
};

}  // namespace isopatch::python
