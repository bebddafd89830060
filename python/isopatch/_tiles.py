"""The tasks of a run in tiles by planes (isopatch.distributed, split="planes") and the merge of their
files.

The driver makes the plan (the tiles' planes, kept clear of the surface at the lattice's corners, the
level and the edge). Then one task per face of the lattice traces the curves of f = 0 on it and writes
them (the data both tiles beside the face read); then one task per tile makes the tile's base in its
box with its cut on those curves, refines it with the cut held, and writes the tile. The tiles are
joined by their boundary vertices, equal bit for bit: a tile's vertex on a face an earlier tile has
is that tile's. Every file is written under a temporary name and renamed, named by the job's hash, and
reused when a driver runs the same job again.
"""

import os
import time
import zipfile
from typing import Any, Dict, List, Sequence, Tuple

import numpy as np

from . import _blocks, _isopatch
from ._errors import InputError, LimitError

#: A tile's refinement holds, per output vertex, as much as a block's; its base and clean-up add little.
BYTES_PER_VERTEX = _blocks.BYTES_PER_VERTEX

_STATE: Dict[str, Any] = {}


def job_state(job: Dict[str, Any]) -> Any:
    """The job's _isopatch.TileJob in this process (its surface made once per job)."""
    state = _STATE.get(job["hash"])
    if state is None:
        state = _isopatch.TileJob(job["source"], job["box"])
        _STATE.clear()
        _STATE[job["hash"]] = state
    return state


def _path(job: Dict[str, Any], name: str) -> str:
    return os.path.join(job["out_dir"], name)


def plan_path(job: Dict[str, Any]) -> str:
    return _path(job, "plan-%s.npz" % job["hash"])


def face_path(job: Dict[str, Any], face: int) -> str:
    return _path(job, "face-%s-%05d.npz" % (job["hash"], face))


def tile_path(job: Dict[str, Any], tile: int) -> str:
    return _path(job, "tile-%s-%05d-of-%05d.npz" % (job["hash"], tile, job["tile_count"]))


def make_plan(job: Dict[str, Any]) -> Dict[str, Any]:
    """The job's plan (made once and written; read back when it exists)."""
    path = plan_path(job)
    if not os.path.exists(path):
        plan = job_state(job).plan(job["options"], job["blocks"])
        arrays = {"level": np.array(plan["level"]), "edge": np.array(plan["edge"]),
                  "counts": np.array(plan["counts"]), "estimated_vertices": np.array(plan["estimated_vertices"])}
        for a, planes in enumerate(plan["planes"]):
            arrays["planes%d" % a] = np.asarray(planes, dtype=np.float64)
        _blocks._write_npz(path, arrays)
    data = _blocks._load(path)
    counts = [int(c) for c in data["counts"]]
    return {"level": int(data["level"]), "edge": float(data["edge"]), "counts": counts,
            "planes": [data["planes%d" % a] for a in range(3)],
            "estimated_vertices": float(data["estimated_vertices"])}


def face_count(counts: Sequence[int]) -> int:
    return sum((counts[a] + 1) * counts[(a + 1) % 3] * counts[(a + 2) % 3] for a in range(3))


def face_number(counts: Sequence[int], axis: int, index: int, cell: Tuple[int, int]) -> int:
    """The number of a face in the lattice's list (isopatch/tiles.hpp grid_faces: axis, plane, cells)."""
    first = sum((counts[a] + 1) * counts[(a + 1) % 3] * counts[(a + 2) % 3] for a in range(axis))
    u, v = counts[(axis + 1) % 3], counts[(axis + 2) % 3]
    return first + (index * u + cell[0]) * v + cell[1]


def tile_cell(counts: Sequence[int], tile: int) -> Tuple[int, int, int]:
    return tile % counts[0], (tile // counts[0]) % counts[1], tile // (counts[0] * counts[1])


def tile_face_numbers(counts: Sequence[int], tile: int) -> List[int]:
    """The numbers of a tile's six faces, in the order x lo, x hi, y lo, y hi, z lo, z hi."""
    cell = tile_cell(counts, tile)
    out = []
    for a in range(3):
        other = (cell[(a + 1) % 3], cell[(a + 2) % 3])
        out += [face_number(counts, a, cell[a], other), face_number(counts, a, cell[a] + 1, other)]
    return out


def run_face(job: Dict[str, Any], face: int) -> Dict[str, Any]:
    """Traces the curves of one face and writes them (or finds them written). Idempotent."""
    path = face_path(job, face)
    reused = os.path.exists(path)
    if not reused:
        curves = job_state(job).face(job["options"], job["plan"], face)
        _blocks._write_npz(path, {"face": np.array(curves["face"]), "spacing": np.array(curves["spacing"]),
                                  "points": curves["points"], "offsets": curves["offsets"],
                                  "indices": curves["indices"]})
    return {"face": face, "reused": reused, "sha256": _blocks.file_digest(path)}


def _read_face(job: Dict[str, Any], face: int) -> Dict[str, Any]:
    data = _blocks._load(face_path(job, face))
    return {"face": [int(v) for v in data["face"]], "spacing": float(data["spacing"]), "points": data["points"],
            "offsets": data["offsets"], "indices": data["indices"]}


def run_tile(job: Dict[str, Any], tile: int) -> Dict[str, Any]:
    """Meshes one tile (its base on its faces' curves, refined) and writes it (or finds it written).
    Idempotent. Raises LimitError when the tile would need more memory than its worker's limit."""
    path = tile_path(job, tile)
    if os.path.exists(path):
        try:
            return dict(_blocks.summary(tile, path, True, _blocks._load(path), 0.0), tile=tile)
        except (OSError, ValueError, KeyError, zipfile.BadZipFile):
            pass  # damaged or foreign: made again
    _blocks._kill_once(job, tile)
    # The estimate is a lower bound of the whole output; a tile may hold twice its share.
    _blocks.refuse_beyond_memory(int(BYTES_PER_VERTEX * 2.0 * job["plan"]["estimated_vertices"] / job["tile_count"]),
                                 "tile", tile, job["tile_count"])
    options = dict(job["options"])
    threads = _blocks._worker_threads()
    if threads > 0:
        options["threads"] = threads
    start = time.perf_counter()
    faces = [_read_face(job, f) for f in tile_face_numbers(job["plan"]["counts"], tile)]
    result = job_state(job).tile(options, job["plan"], tile, faces)
    arrays = {k: (v if isinstance(v, np.ndarray) else np.array(v)) for k, v in result.items()}
    _blocks._write_npz(path, arrays)
    return dict(_blocks.summary(tile, path, False, arrays, time.perf_counter() - start), tile=tile)


def number_tiles(job: Dict[str, Any]) -> Dict[str, Any]:
    """The whole output's numbers: tiles in order, a tile's boundary vertex that an earlier tile has (the
    same position bit for bit) given that tile's number. Returns per tile the numbers of its vertices
    and which it owns, and the counts. Raises InputError when a boundary vertex inside the domain has no
    copy in another tile (files of different runs mixed)."""
    planes = job["plan"]["planes"]
    lo = np.array([p[0] for p in planes]).view(np.uint64)
    hi = np.array([p[-1] for p in planes]).view(np.uint64)
    shared: Dict[bytes, int] = {}
    copies: Dict[bytes, int] = {}
    numbers: List[np.ndarray] = []
    owned: List[np.ndarray] = []
    total = 0
    triangles = 0
    for tile in range(job["tile_count"]):
        data = _blocks._load(tile_path(job, tile), ("positions", "boundary", "triangles"))
        positions = np.ascontiguousarray(data["positions"], dtype="<f8")
        n = positions.shape[0]
        number = np.empty(n, dtype=np.uint64)
        mine = np.ones(n, dtype=bool)
        rows = positions.view(np.uint64).reshape(n, 3)
        boundary = np.flatnonzero(data["boundary"])
        keys = [rows[v].tobytes() for v in boundary]
        for v, key in zip(boundary, keys):
            found = shared.get(key)
            if found is not None:
                number[v] = found
                mine[v] = False
                copies[key] += 1
        order = np.flatnonzero(mine)
        number[order] = total + np.arange(order.size, dtype=np.uint64)
        total += int(order.size)
        for v, key in zip(boundary, keys):
            if mine[v]:
                shared[key] = int(number[v])
                on_domain = bool(np.any(rows[v] == lo) or np.any(rows[v] == hi))
                copies[key] = 2 if on_domain else 1
        numbers.append(number)
        owned.append(mine)
        triangles += int(data["triangles"].shape[0])
    alone = sum(1 for c in copies.values() if c < 2)
    if alone:
        raise InputError("%d vertices on the tiles' inner faces have no copy across (tile files of different runs "
                         "mixed in %s?)" % (alone, job["out_dir"]))
    return {"numbers": numbers, "owned": owned, "vertices": total, "triangles": triangles,
            "seam_vertices": len(copies)}


def seam_band_angles(vertices: np.ndarray, faces: np.ndarray, planes: Sequence[Sequence[float]],
                     width: float) -> Tuple[float, float, float]:
    """The smallest angle (degrees) of the triangles with a corner within `width` of an inner plane of
    a tiled run (the seam band: pass the base edge, edge length times level) and of the others, and the
    band's share of the triangles. `planes`: the manifest's."""
    near = np.zeros(len(vertices), dtype=bool)
    for axis, coordinates in enumerate(planes):
        for at in coordinates[1:-1]:
            near |= np.abs(vertices[:, axis] - at) < width
    a, b, c = (vertices[faces[:, k]] for k in range(3))

    def angle(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> np.ndarray:
        u, v = q - p, r - p
        return np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v), axis=1), np.einsum("ij,ij->i", u, v)))

    smallest = np.minimum(np.minimum(angle(a, b, c), angle(b, c, a)), angle(c, a, b))
    band = near[faces].any(axis=1)
    return (float(smallest[band].min()) if band.any() else 180.0,
            float(smallest[~band].min()) if (~band).any() else 180.0, float(band.mean()))


def write_ply(job: Dict[str, Any], numbering: Dict[str, Any], path: str) -> None:
    """One binary PLY of the whole output, streamed tile by tile: the bytes do not depend on the order
    the tiles were made in."""
    _blocks.stream_ply(path, numbering["vertices"], numbering["triangles"], job["tile_count"],
                       lambda t: _blocks._load(tile_path(job, t), ("positions",))["positions"][numbering["owned"][t]],
                       lambda t: numbering["numbers"][t][_blocks._load(tile_path(job, t), ("triangles",))["triangles"]])


def write_other(job: Dict[str, Any], numbering: Dict[str, Any], path: str) -> None:
    """Any other format isopatch writes (.3mf, .stl, ...), through one mesh in memory."""
    if numbering["vertices"] >= 2 ** 32 - 1:
        raise LimitError("the output is too large for one mesh in memory: write a .ply or keep the tiles")
    positions: List[np.ndarray] = []
    faces: List[np.ndarray] = []
    for tile in range(job["tile_count"]):
        data = _blocks._load(tile_path(job, tile), ("positions", "triangles"))
        positions.append(data["positions"][numbering["owned"][tile]])
        faces.append(numbering["numbers"][tile][data["triangles"]].astype(np.uint32))
    _isopatch.write_arrays(np.concatenate(positions), np.concatenate(faces), path)
