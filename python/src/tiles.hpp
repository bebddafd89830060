#pragma once
// isopatch._isopatch's tiles by planes (isopatch/tiles.hpp) for isopatch.distributed: the plan, one
// face's curves and one tile's mesh, as NumPy arrays a task can write to a file.

#include <pybind11/pybind11.h>

namespace isopatch::python {

/// Binds TileJob (a source and box; its plan, faces and tiles).
void bind_tiles(pybind11::module_& m);

}  // namespace isopatch::python
