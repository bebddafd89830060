#pragma once
// analyze_quality()'s report (metrics.hpp) as nested Python dicts, under the keys of the command
// line's `isopatch analyze --json` (undefined statistics are NaN).

#include <pybind11/pybind11.h>
#include <isopatch/metrics.hpp>

namespace isopatch::python {

/// topology, self_intersections, shape, valence and (when measured) accuracy, each a dict.
pybind11::dict report_dict(const QualityReport& report);

}  // namespace isopatch::python
