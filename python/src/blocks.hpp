#pragma once
// isopatch._isopatch's blocked meshing (isopatch/blocks.hpp) for isopatch.distributed: the base, the
// plan, one block refined, as NumPy arrays a task can write to a file.

#include <pybind11/pybind11.h>

namespace isopatch::python {

/// Binds block_base, BlockJob (a base, its plan and its blocks refined) and write_arrays.
void bind_blocks(pybind11::module_& m);

}  // namespace isopatch::python
