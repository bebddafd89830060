#pragma once
// The arguments every binding shares: an optional box as two triples, and the settings the Python
// wrapper passes as keyword arguments (only those not None).

#include <pybind11/pybind11.h>
#include <isopatch/geometry.hpp>
#include <isopatch/settings.hpp>

#include <array>
#include <optional>
#include <utility>

namespace isopatch::python {

using BoxArg = std::optional<std::pair<std::array<double, 3>, std::array<double, 3>>>;

/// The box of two corners, or none. \throw InputError for an invalid box (valid_box).
std::optional<Box> to_box(const BoxArg& arg);

/// Settings from keyword arguments. \throw InputError for an unknown name, SettingError for a value of
/// the wrong type or out of range.
Settings to_settings(const pybind11::dict& options);

}  // namespace isopatch::python
