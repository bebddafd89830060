"""The entry points: mesh() for formulas, catalogue names and Python functions, mesh_volume() for
sampled 3D arrays, volume files and OpenVDB grids, read_volume() for .npy and .nrrd files."""

from __future__ import annotations

import os
import time
from typing import Any, Callable, Dict, Literal, Optional, Sequence, Tuple, Union

import numpy as np

from . import _isopatch, _vdb
from ._errors import InputError
from ._mesh import Mesh

Point = Tuple[float, float, float]
BoxLike = Tuple[Sequence[float], Sequence[float]]
Function = Callable[[np.ndarray], np.ndarray]
#: The string options, as type checkers see them (the library refuses any other value at run time).
Quality = Literal["preview", "default", "fine"]
Method = Literal["projection", "mc"]
Creases = Literal["auto", "off", "exact"]
Inside = Literal["below", "above"]
#: A convex region: the command line's --region text ("a,b,c,d;...") or (a, b, c, d) planes, each the
#: half-space a x + b y + c z + d <= 0; a frame: "AZ,EL,ROLL" or three angles in degrees.
Region = Union[str, Sequence[Sequence[float]]]
FrameLike = Union[str, Sequence[float]]


def _box(box: Optional[BoxLike]) -> Optional[Tuple[Point, Point]]:
    if box is None:
        return None
    try:
        lo, hi = box
        lo = tuple(float(v) for v in lo)
        hi = tuple(float(v) for v in hi)
    except (TypeError, ValueError):
        raise InputError("box must be ((x0, y0, z0), (x1, y1, z1))", "box") from None
    if len(lo) != 3 or len(hi) != 3:
        raise InputError("box must be ((x0, y0, z0), (x1, y1, z1))", "box")
    return lo, hi  # type: ignore[return-value]


def _triple(value: Sequence[float], name: str) -> Point:
    try:
        t = tuple(float(v) for v in value)
    except TypeError:
        t = (float(value),) * 3  # type: ignore[arg-type]
    if len(t) != 3:
        raise InputError(f"{name} must be three numbers", name)
    return t  # type: ignore[return-value]


# The library settings both entry points take (the command line's flags of the same names).
_SETTINGS = (
    "method", "edge_length", "max_error", "quality", "threads", "remesh", "refine", "max_vertices", "time_limit",
    "uniform")


def _options(arguments: Dict[str, object], names: Sequence[str]) -> Dict[str, object]:
    """The settings among `arguments` (a call's locals()) named in `names`, without those left None."""
    return {name: arguments[name] for name in names if arguments[name] is not None}


def mesh(
    surface: Union[str, Function],
    box: Optional[BoxLike] = None,
    *,
    gradient: Optional[Function] = None,
    params: Optional[Dict[str, float]] = None,
    edge_length: Optional[float] = None,
    max_error: Optional[float] = None,
    quality: Quality = "default",
    threads: int = 0,
    method: Method = "projection",
    remesh: Optional[int] = None,
    refine: int = 0,
    resolution: Optional[int] = None,
    grid: Optional[int] = None,
    max_vertices: int = 0,
    max_evaluations: int = 0,
    time_limit: float = 0.0,
    uniform: bool = False,
    creases: Creases = "auto",
    region: Optional[Region] = None,
    frame: Optional[FrameLike] = None,
    samples: Optional[int] = None,
    batch: int = 1 << 18,
) -> Mesh:
    """Meshes the surface f = 0 (f < 0 inside) inside ``box``.

    surface: a formula of the expression language (``'x^2+y^2+z^2-1'``; ``^`` is a power), a catalogue
        name (``'torus'``, see :func:`catalogue`), a composite surface's ``.ipatch`` file (I-patches,
        setback vertex blends: its patches meshed along their boundary curves, docs/ipatch.md) or a
        Python function taking an (N, 3) float64 array of points and returning N values (f < 0 inside).
    box: ((x0, y0, z0), (x1, y1, z1)); required for formulas and functions, optional for catalogue
        names and composites (their own box by default).
    gradient: with a Python function, an optional second function returning the (N, 3) gradients;
        without it, gradients come from central differences (step 6e-6 of the box diagonal).
    params: values overriding a formula's definitions (``{'r': 0.3}``).
    edge_length, max_error, quality ('preview' | 'default' | 'fine'), threads (0: every core), method
        ('projection' | 'mc'), remesh, refine (0: automatic multiresolution level, 1: off, 2..16: that
        level), resolution, grid, max_vertices, max_evaluations, time_limit, uniform (one edge length
        even where the box cuts the surface in features narrower than an edge, or where the surface
        turns within an edge, as at a thin rim): the library's
        settings, as the command line's flags of the same names.
    creases: formulas only. 'auto': a formula built with min, max or abs whose faces meet at real creases
        (a CSG shape) is meshed along its exact creases and corners (docs/creases.md); where the crease
        paths cannot follow them, as a smooth surface with ``stats['warnings']['creases_rounded']``;
        'exact': the same, but such a shape raises CreaseError with the reason; 'off': meshed as a smooth
        surface. Raises CreaseError for a shape no mesh can follow (solids touching along an edge).
    region, frame: formulas and catalogue names, projection only, as the command line's --region and
        --frame: mesh inside the convex polytope of the region's half-spaces (inside the box when given;
        a formula without a box takes a bounded region's bounds), or partition in a frame rotated by
        azimuth, elevation and roll (docs/convex-partitions.md).
    samples, batch: Python functions only. The function is called in batches of at most ``batch``
        points: first on a grid of ``samples`` cells along the box's longest side (default: two per
        target edge, 64..256), whose tricubic B-spline interpolant is meshed, then for a few batched
        Newton steps that move every vertex onto f = 0 itself (``stats['python']`` counts the calls).

    Meshing releases the GIL (a Python function is only called, with the GIL, before and after it);
    Ctrl-C stops it with KeyboardInterrupt. Raises the isopatch exceptions (isopatch.Error and its
    subclasses) with the library's messages; an exception raised by the function propagates unchanged.
    """
    started = time.perf_counter()
    options = _options(locals(), _SETTINGS + ("resolution", "grid", "max_evaluations", "creases", "region", "frame"))
    if not isinstance(surface, str) and (region is not None or frame is not None):
        raise InputError("region and frame are for formulas and catalogue names", "region")
    if isinstance(surface, str):
        if gradient is not None or samples is not None:
            raise InputError("gradient and samples are for Python functions, not formulas", "gradient")
        result = _isopatch.mesh_spec(surface, _box(box), dict(params or {}), options)
    elif callable(surface):
        if params:
            raise InputError("params are for formulas, not Python functions", "params")
        if gradient is not None and not callable(gradient):
            raise InputError("gradient must be a function of an (N, 3) array", "gradient")
        result = _isopatch.mesh_callable(surface, gradient, _box(box), samples, int(batch), options)
    else:
        raise InputError("surface must be a formula, a catalogue name or a function", "surface")
    return Mesh(result, started)


def mesh_volume(
    volume: Union[np.ndarray, str, "os.PathLike[str]", Any],
    level: float = 0.0,
    spacing: Optional[Sequence[float]] = None,
    origin: Optional[Sequence[float]] = None,
    *,
    grid: Optional[str] = None,
    inside: Inside = "below",
    box: Optional[BoxLike] = None,
    edge_length: Optional[float] = None,
    max_error: Optional[float] = None,
    quality: Quality = "default",
    threads: int = 0,
    method: Method = "projection",
    remesh: Optional[int] = None,
    refine: int = 0,
    max_vertices: int = 0,
    time_limit: float = 0.0,
    uniform: bool = False,
) -> Mesh:
    """Meshes the level set ``volume == level`` of sampled values: a 3D array, a .npy, .nrrd or .vdb
    file's path, or an OpenVDB grid object (Debian's python3-openvdb, ``import pyopenvdb``).

    Arrays: axis order as in scikit-image's marching_cubes: ``volume[i, j, k]`` is the sample at
    ``origin + (i * spacing[0], j * spacing[1], k * spacing[2])`` (spacing 1 and origin 0 unless
    given; a .npy or .nrrd file's own unless given), so vertex column 0 is along array axis 0. The mesh
    lies on the tricubic B-spline that interpolates the samples (C2, so gradients and curvatures exist).

    OpenVDB (.vdb path or grid object): ``grid`` names the grid of a file (default: its only level set,
    else its only float or double grid); spacing and origin come from the grid's transform (giving them
    is an InputError). The mesh lies on a tricubic B-spline over the voxels (their cubic
    quasi-interpolant, C2), built and stored only around the grid's leaves: memory follows the active
    voxels, not the bounding box. Outside a level set's narrow band the grid's inactive values hold f
    constant, so nothing is meshed there; the default region spans the active voxels.

    ``inside='below'`` (signed distances, level sets): values below ``level`` are inside, normals point
    towards higher values; ``inside='above'`` (densities, CT, masks, fog volumes): values above are
    inside, normals point towards lower values.
    The region is the samples' extent unless ``box`` is given. Other settings as :func:`mesh`.
    Raises InputError for an array that is not 3D, has a side below 2 samples, or holds NaN or
    infinity (the message names the index), or an unknown grid name; IoError for an unreadable,
    malformed or unsupported file; NoSurfaceError when no sample crosses ``level``.
    """
    started = time.perf_counter()
    options = _options(locals(), _SETTINGS)
    if inside not in ("below", "above"):
        raise InputError(f"inside must be 'below' or 'above', not {inside!r}", "inside")
    if _vdb.is_vdb_path(volume) or _vdb.is_openvdb_grid(volume):
        if spacing is not None or origin is not None:
            raise InputError("spacing and origin come from an OpenVDB grid's transform", "spacing")
        return Mesh(_vdb.mesh_vdb(volume, grid, level, inside == "above", _box(box), options), started)
    if grid is not None:
        raise InputError("grid= names a grid of a .vdb file or object", "grid")
    if isinstance(volume, (str, os.PathLike)):  # a .npy or .nrrd file: its samples, spacing and origin
        array, file_spacing, file_origin = read_volume(os.fspath(volume))
        spacing = file_spacing if spacing is None else spacing
        origin = file_origin if origin is None else origin
    else:
        array = volume
    array = np.ascontiguousarray(array, dtype=np.float64)
    if inside == "above":  # the same surface with f's sign turned: outward normals for densities
        array, level = -array, -level
    result = _isopatch.mesh_volume(
        array, float(level), _triple((1.0, 1.0, 1.0) if spacing is None else spacing, "spacing"),
        _triple((0.0, 0.0, 0.0) if origin is None else origin, "origin"), _box(box), options
    )
    return Mesh(result, started)


def read_volume(path: str) -> Tuple[np.ndarray, Point, Point]:
    """Reads a .npy or .nrrd volume: (samples as a float64 3D array, spacing, origin), in the axis
    order of :func:`mesh_volume` (a NRRD file's fastest axis is axis 0). Raises IoError for an
    unreadable, malformed, truncated or unsupported file (the message names it)."""
    return _isopatch.read_volume(str(path))


def catalogue() -> list:
    """The names of the built-in surfaces (``isopatch surfaces`` on the command line)."""
    return list(_isopatch.catalogue())
