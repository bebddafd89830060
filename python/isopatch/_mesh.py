"""The result of meshing: numpy arrays, per-vertex fields, statistics, files and pictures."""

from __future__ import annotations

import time

from functools import cached_property
from typing import Any, Dict, Literal, Optional, Sequence

import numpy as np

from ._errors import InputError

#: render()'s `show` values, as type checkers see them.
Show = Literal["shaded", "wireframe", "isophotes", "mean-curvature", "gaussian-curvature", "error", "field"]

# render()'s `show` values, as the command line's `isopatch render --show`: (mode, default field).
# Modes are RenderMode's values (render.hpp): Shaded 0, Wireframe 1, ScalarField 2, Isophotes 3, Error 4.
_SHOW = {
    "shaded": (0, ""),
    "wireframe": (1, ""),
    "isophotes": (3, ""),
    "mean-curvature": (2, "mean_curvature"),
    "gaussian-curvature": (2, "gaussian_curvature"),
    "error": (4, "distance"),
    "field": (2, ""),
}


class Mesh:
    """A triangle mesh of f = 0, counter-clockwise seen from outside (normals along grad f).

    vertices: (V, 3) float64; faces: (F, 3) int64 indices into vertices; normals: (V, 3) float64 unit
    gradients of f at the vertices. The arrays are computed once and shared (do not write into them).

    Interop, without copying by hand:
        meshio.Mesh(m.vertices, [("triangle", m.faces)], point_data=m.fields)
        trimesh.Trimesh(m.vertices, m.faces, vertex_normals=m.normals)
        open3d.geometry.TriangleMesh(Vector3dVector(m.vertices), Vector3iVector(m.faces))
        pyvista.PolyData(m.vertices, np.hstack([np.full((len(m.faces), 1), 3), m.faces]))
    """

    @staticmethod
    def from_arrays(vertices: np.ndarray, faces: np.ndarray, surface: str, box: Any = None) -> "Mesh":
        """Any triangle mesh (e.g. scikit-image's marching_cubes output) with the surface it stands for
        (a formula or catalogue name, as :func:`isopatch.mesh` takes them), so that :meth:`analyze`,
        :attr:`fields` and :meth:`render` measure it the same way as isopatch's own meshes. ``normals``
        are the surface's unit gradients at the vertices. Raises InputError for malformed arrays."""
        from . import _isopatch
        from ._api import _box

        return Mesh(_isopatch.mesh_from_arrays(vertices, faces, surface, _box(box)))

    def __init__(self, result: Any, started: Optional[float] = None) -> None:
        self._result = result
        # The call that made the mesh, from its start (time.perf_counter()) to its return.
        self._total = None if started is None else time.perf_counter() - started

    @cached_property
    def vertices(self) -> np.ndarray:
        return self._result.vertices()

    @cached_property
    def faces(self) -> np.ndarray:
        return self._result.faces()

    @cached_property
    def normals(self) -> np.ndarray:
        return self._result.normals()

    @cached_property
    def fields(self) -> Dict[str, np.ndarray]:
        """Per-vertex float64 arrays: mean_curvature and gaussian_curvature (discrete, from the mesh;
        NaN on boundary vertices), mean_curvature_exact and gaussian_curvature_exact (of the level set
        through the vertex, from f's derivatives; for a Python function, from its samples'
        interpolant), distance (f / |grad f|, signed, > 0 outside; of the function itself)."""
        return self._result.fields()

    @property
    def stats(self) -> Dict[str, Dict[str, float]]:
        """Every statistic of the run by stage and name, as ``isopatch mesh --stats-json`` writes them
        (stage 'mesh': seconds, evaluations, vertices, triangles; ...; 'python': calls into a Python
        function). ``stats['seconds']['total']`` is the whole call of isopatch.mesh or mesh_volume that made
        the mesh, from the call to its return; the other entries of 'seconds' are its stages."""
        stats = self._result.stats()
        if self._total is not None:
            stats.setdefault("seconds", {})["total"] = self._total
        return stats

    def write(self, path: str, fields: bool = False) -> None:
        """Writes the mesh, the format from the extension (.ply, .obj, .off, .stl, .glb, .3mf). With fields=True the
        fields are stored as PLY vertex attributes. The file is written whole or not at all (a temporary file
        beside it, renamed at the end): IoError when it cannot be written, KeyboardInterrupt on Ctrl-C, and
        either way no temporary file is left and a file already at `path` stays as it was."""
        self._result.write(str(path), bool(fields))

    def analyze(self, surface: bool = True) -> Dict[str, Any]:
        """Topology, self-intersections, element shape, valence and (surface=True) accuracy against
        the surface meshed, as ``isopatch analyze --json`` reports them (nested dicts). For a Python
        function the accuracy is measured against the interpolant of its samples (``fields['distance']``
        is the distance to f = 0 of the function itself)."""
        return self._result.analyze(bool(surface))

    def render(
        self,
        path: Optional[str] = None,
        *,
        show: Show = "shaded",
        field: Optional[str] = None,
        values: Optional[Sequence[float]] = None,
        size: Sequence[int] = (800, 800),
        view: Sequence[float] = (30.0, 25.0),
        orthographic: bool = False,
        range: Optional[float] = None,
        legend: bool = True,
        caption: str = "",
    ) -> np.ndarray:
        """A picture of the mesh as an (height, width, 3) uint8 RGB array, also written as PNG to
        ``path`` when given. show: shaded | wireframe | isophotes | mean-curvature | gaussian-curvature |
        error | field (with ``field`` naming one of :attr:`fields`, or ``values`` one per vertex), as
        ``isopatch render --show``; view: (azimuth, elevation) in degrees, z up."""
        if show not in _SHOW:
            raise InputError(f"unknown show '{show}' (want {', '.join(_SHOW)})", "show")
        mode, default_field = _SHOW[show]
        if show == "field" and field is None and values is None:
            raise InputError("show='field' needs field= or values=", "field")
        vals = [] if values is None else [float(v) for v in np.asarray(values, dtype=np.float64).ravel()]
        width, height = (int(s) for s in size)
        azimuth, elevation = (float(v) for v in view)
        return self._result.render(
            mode, field or default_field, vals, width, height, azimuth, elevation, bool(orthographic),
            range, bool(legend), caption, "" if path is None else str(path)
        )

    def __repr__(self) -> str:
        return (
            f"<isopatch.Mesh of {self._result.surface_name()}: {len(self.vertices)} vertices, "
            f"{len(self.faces)} triangles>"
        )
