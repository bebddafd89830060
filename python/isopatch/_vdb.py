"""OpenVDB grids for mesh_volume(): a .vdb file's name, or a grid object of Debian's python3-openvdb
(pyopenvdb), which is written to a temporary .vdb file and read back by the library (the grid's own
bytes, so nothing is densified on the way: memory follows the active voxels)."""

from __future__ import annotations

import os
import tempfile
from typing import Any, Dict, List, Optional, Tuple

from . import _isopatch
from ._errors import InputError

Point = Tuple[float, float, float]


def is_openvdb_grid(value: Any) -> bool:
    """True for a pyopenvdb grid object (FloatGrid, DoubleGrid, ...)."""
    module = type(value).__module__ or ""
    return module.split(".")[0] == "pyopenvdb"


def is_vdb_path(value: Any) -> bool:
    return isinstance(value, (str, os.PathLike)) and os.fspath(value).lower().endswith(".vdb")


def mesh_vdb(source: Any, grid: Optional[str], level: float, inside_above: bool,
             box: Optional[Tuple[Point, Point]], options: Dict[str, object]) -> Any:
    """The compiled module's result for a .vdb path or a pyopenvdb grid (see mesh_volume)."""
    if is_openvdb_grid(source):
        import pyopenvdb  # type: ignore[import]  # the caller has it: the grid is one of its objects (untyped)

        if grid is not None:
            raise InputError("grid= names a grid of a .vdb file; a grid object is meshed as it is", "grid")
        with tempfile.TemporaryDirectory(prefix="isopatch-vdb-") as scratch:
            path = os.path.join(scratch, "grid.vdb")
            copy = source.copy()  # shares the tree; only the name may change
            copy.name = source.name or "grid"
            pyopenvdb.write(path, grids=[copy])
            return _isopatch.mesh_vdb(path, copy.name, float(level), inside_above, box, options)
    return _isopatch.mesh_vdb(os.fspath(source), grid or "", float(level), inside_above, box, options)


def vdb_grids(path: str) -> List[Dict[str, object]]:
    """The grids of a .vdb file: dicts with ``name``, ``value_type``, ``grid_class`` and
    ``active_voxels`` (0 when the file does not record it), in file order. Raises IoError for a file
    that cannot be read or is not an OpenVDB file."""
    return list(_isopatch.vdb_grids(os.fspath(path)))
