"""isopatch: good-quality triangle meshes of implicit surfaces f(x, y, z) = 0, numpy in, numpy out.

Surfaces are formulas (``'x^2+y^2+z^2-1'``), catalogue names (``'torus'``), Python functions of an
(N, 3) array, or sampled 3D arrays, volume files and OpenVDB grids (:func:`mesh_volume`). Results are :class:`Mesh` objects with
``vertices``, ``faces``, ``normals``, per-vertex ``fields`` and ``stats``; see docs/python.md.
"""

from ._api import catalogue, mesh, mesh_volume, read_volume
from ._errors import (
    CreaseError,
    Error,
    EvaluationError,
    InputError,
    InternalError,
    IoError,
    LimitError,
    NoSurfaceError,
    ParseError,
    SettingError,
    SingularSurfaceError,
    UnknownSurfaceError,
)
from ._isopatch import __version__  # the library's version: project(isopatch VERSION ...) in CMake
from ._mesh import Mesh
from ._vdb import vdb_grids

__all__ = [
    "__version__",
    "mesh",
    "mesh_volume",
    "read_volume",
    "vdb_grids",
    "catalogue",
    "Mesh",
    "CreaseError",
    "Error",
    "EvaluationError",
    "InputError",
    "InternalError",
    "IoError",
    "LimitError",
    "NoSurfaceError",
    "ParseError",
    "SettingError",
    "SingularSurfaceError",
    "UnknownSurfaceError",
]
