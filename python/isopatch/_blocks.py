"""The tasks of a blocked run (isopatch.distributed) and the merge of their files.

A job is a plain dict, the same on the driver and on every worker: the surface's source, box and
settings, the number of blocks, the refinement level, the output directory and the hash that names
its files. Every file is written under a temporary name and renamed, so a task that runs twice (a
retried or duplicated Dask task) leaves one complete file, and a driver run again with the same job
finds the files of the blocks already done and reuses them.
"""

import functools
import hashlib
import json
import os
import resource
import time
import zipfile
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _isopatch
from ._errors import InputError, LimitError

FORMAT = "isopatch-blocks/1"
#: Bytes a block's refinement takes per output vertex at its peak: the refined mesh, its normals,
#: relaxation and repair state and the arrays handed back (measured: 197 on gyroid blocks of 0.5M and
#: 1.4M vertices, docs/distributed.md), with room for the file written.
BYTES_PER_VERTEX = 300
#: The PLY header isopatch's own writer puts before a mesh without attributes (src/mesh/ply_io.cpp).
_PLY_HEADER = (
    "ply\nformat binary_little_endian 1.0\ncomment isopatch mesh\nelement vertex {v}\n"
    "property double x\nproperty double y\nproperty double z\nelement face {t}\n"
    "property list uchar {index} vertex_indices\nend_header\n"
)


def file_digest(path: str) -> str:
    """The SHA-256 of a file's bytes, in hex."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


#: A composite base's arrays (the patch of every triangle, the curves' segments and vertices).
_PATCH_KEYS = ("triangle_patch", "curve_segments", "curve_offsets", "curve_vertices")


def is_composite(source: Dict[str, Any]) -> bool:
    """Whether the source names a composite surface (a .ipatch file)."""
    spec = source.get("spec", "")
    return "volume" not in source and isinstance(spec, str) and spec.endswith(".ipatch") and len(spec) > 7


def job_hash(job: Dict[str, Any]) -> str:
    """A hash of everything that decides a job's bytes: the library version, the source (and the bytes
    of a file it names), the box, the settings and the number of blocks."""
    # A volume's coefficients and grid are made from its bytes (hashed) and the prefilter window.
    source = {k: v for k, v in job["source"].items() if k not in ("coefficients", "spacing", "origin")}
    if "volume" in source and "volume_sha256" not in source:
        source["volume_sha256"] = file_digest(source["volume"])
    spec = source.get("spec", "")
    if isinstance(spec, str) and spec.startswith("@"):
        source["spec_sha256"] = file_digest(spec[1:])
    elif is_composite(source):
        source["spec_sha256"] = file_digest(spec)
    described = {
        "format": FORMAT,
        "version": _isopatch.__version__,
        "source": source,
        "box": job["box"],
        "options": {k: v for k, v in job["options"].items() if k != "threads"},
        "blocks": job["blocks"],
    }
    if job.get("split", "blocks") != "blocks":
        described["split"] = job["split"]  # tiles by planes (the hashes of blocked runs stay as they were)
    if "part" in job:
        described["part"] = job["part"]  # one part's cut of a capped lattice
    text = json.dumps(described, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _path(job: Dict[str, Any], name: str) -> str:
    return os.path.join(job["out_dir"], name)


def base_path(job: Dict[str, Any]) -> str:
    return _path(job, "base-%s.npz" % job["hash"])


def block_path(job: Dict[str, Any], block: int) -> str:
    return _path(job, "block-%s-%05d-of-%05d.npz" % (job["hash"], block, job["blocks"]))


def manifest_path(job: Dict[str, Any]) -> str:
    return _path(job, "manifest-%s.json" % job["hash"])


def _write_npz(path: str, arrays: Dict[str, np.ndarray]) -> None:
    """Writes arrays to `path` under a temporary name (unique to this process) and renames it."""
    tmp = "%s.tmp-%d-%d" % (path, os.getpid(), time.monotonic_ns())
    with open(tmp, "wb") as f:
        np.savez(f, **arrays)
    os.replace(tmp, path)


def _load(path: str, keys: Optional[Sequence[str]] = None) -> Dict[str, np.ndarray]:
    """The arrays of an .npz file (only `keys` when given: the others are not read)."""
    with np.load(path, allow_pickle=False) as data:
        return {k: data[k] for k in (data.files if keys is None else keys)}


#: This process's BlockJob (the base, its plan and its surface), by job hash: a worker reads and plans
#: the base and compiles the formula (or maps a volume's coefficients) once per job, not once per block.
_STATE: Dict[str, Any] = {}


def job_state(job: Dict[str, Any]) -> Any:
    """The job's _isopatch.BlockJob in this process (made on first use; one job is kept)."""
    state = _STATE.get(job["hash"])
    if state is None:
        # A composite's base, or a formula's meshed along its creases, has its pieces' arrays too.
        base = _load(base_path(job))
        patches = {k: base[k] for k in _PATCH_KEYS} if "triangle_patch" in base else None
        state = _isopatch.BlockJob(job["source"], job["box"], base["positions"], base["triangles"], job["level"],
                                   job["blocks"], patches, part=job.get("part", -1))
        _STATE.clear()
        _STATE[job["hash"]] = state
    return state


def make_base(job: Dict[str, Any]) -> int:
    """Makes the job's base file (once; reused when it exists) and returns its refinement level."""
    path = base_path(job)
    if not os.path.exists(path):
        base = _isopatch.block_base(job["source"], job["box"], job["options"], part=job.get("part", -1))
        arrays = {"positions": base["positions"], "triangles": base["triangles"], "level": np.array(base["level"])}
        arrays.update(base.get("patches", {}))
        _write_npz(path, arrays)
    return int(_load(path, ("level",))["level"])


def _worker_memory_limit() -> Optional[int]:
    """The memory limit of the Dask worker running this task (None outside a worker, or unlimited)."""
    try:
        from distributed import get_worker
        worker = get_worker()
    except (ImportError, ValueError):
        return None
    manager = getattr(worker, "memory_manager", None)
    limit = getattr(manager, "memory_limit", None) if manager is not None else None
    if limit is None:
        limit = getattr(worker, "memory_limit", None)
    return int(limit) if limit else None


def _worker_threads() -> int:
    try:
        from distributed import get_worker
        worker = get_worker()
    except (ImportError, ValueError):
        return 0
    state = getattr(worker, "state", None)
    return int(getattr(state, "nthreads", 0) or getattr(worker, "nthreads", 0) or 0)


def _kill_once(job: Dict[str, Any], block: int) -> None:
    """For the tests of lost workers: the first run of a marked block (kill_block, or any of kill_blocks)
    ends its process abruptly, leaving kill_marker (with the block's number after it for kill_blocks)."""
    marker = job.get("kill_marker")
    if not marker:
        return
    if "kill_blocks" in job:
        if block not in job["kill_blocks"]:
            return
        marker = "%s-%d" % (marker, block)
    elif block != job.get("kill_block", 0):
        return
    if not os.path.exists(marker):
        with open(marker, "w") as f:
            f.write("killed block %d in process %d\n" % (block, os.getpid()))
        os._exit(17)


def refuse_beyond_memory(need: int, what: str, number: int, count: int) -> None:
    """Raises LimitError when `need` bytes exceed the worker's memory limit, saying how many `what`s
    ("block", "tile") would fit."""
    limit = _worker_memory_limit()
    if limit is not None and need > limit:
        raise LimitError(
            "%s %d of %d needs about %d MB but its worker's memory limit is %d MB: use more %ss "
            "(--tiles %d or more)" % (what, number, count, need >> 20, limit >> 20, what, count * (need // limit + 1)))


def summary(block: int, path: str, reused: bool, data: Dict[str, np.ndarray], seconds: float) -> Dict[str, Any]:
    """What the manifest says of a block's or tile's file."""
    return {
        "block": block,
        "file": os.path.basename(path),
        "sha256": file_digest(path),
        "vertices": int(data["positions"].shape[0]),
        "triangles": int(data["triangles"].shape[0]),
        "failed_points": int(data["failed_points"]),
        "smallest_angle": float(data["smallest_angle"]),
        "kept": bool(data["kept"]),
        "seam_band_vertices": int(data["seam_band_vertices"]),
        "seconds": seconds,
        "peak_rss_bytes": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024,
        "reused": reused,
    }


def run_block(job: Dict[str, Any], block: int) -> Dict[str, Any]:
    """Refines one block of the job and writes its file (or finds it written). Idempotent.

    Raises LimitError when the block would need more memory than the worker's limit (more blocks make
    each smaller), and the library's errors of the refinement."""
    path = block_path(job, block)
    expected = int(job["plan"]["vertex_count"][block])
    if os.path.exists(path):
        try:
            found = _load(path)
            # A block that was not kept is not kept again with the same settings: its file stands too.
            if not bool(found["kept"]) or found["positions"].shape == (expected, 3):
                return summary(block, path, True, found, 0.0)
        except (OSError, ValueError, KeyError, zipfile.BadZipFile):
            pass  # not a block file of this job (damaged or foreign): made again below
    _kill_once(job, block)
    # The block, and the base with its plan (about four times its file).
    refuse_beyond_memory(BYTES_PER_VERTEX * expected + 4 * os.path.getsize(base_path(job)), "block", block,
                         job["blocks"])
    options = dict(job["options"])
    threads = _worker_threads()
    if threads > 0:
        options["threads"] = threads
    start = time.perf_counter()
    result = job_state(job).refine(options, block)
    arrays = {k: (v if isinstance(v, np.ndarray) else np.array(v)) for k, v in result.items()}
    _write_npz(path, arrays)
    return summary(block, path, False, arrays, time.perf_counter() - start)


def check_seams(job: Dict[str, Any], plan: Dict[str, Any]) -> int:
    """Checks that every block's copy of a seam vertex is its owner's to the bit; returns how many
    copies were checked. Raises InputError naming the first that differs."""
    first = np.asarray(plan["first_vertex"], dtype=np.uint64)
    checked = 0

    # The owner of a seam vertex is a lower block, mostly a recent one along the Morton curve.
    @functools.lru_cache(maxsize=8)
    def positions(block: int) -> np.ndarray:
        return _load(block_path(job, block), ("positions",))["positions"]

    for block in range(job["blocks"]):
        data = _load(block_path(job, block), ("seam_ids", "seam_positions"))
        ids = data["seam_ids"].astype(np.uint64)
        owner = np.searchsorted(first, ids, side="right") - 1
        for o in np.unique(owner):
            mine = owner == o
            theirs = positions(int(o))
            local = (ids[mine] - first[o]).astype(np.int64)
            if not np.array_equal(theirs[local].view(np.uint64), data["seam_positions"][mine].view(np.uint64)):
                raise InputError("block %d's copy of a seam vertex differs from block %d's (files of "
                                 "different runs mixed in %s?)" % (block, int(o), job["out_dir"]))
            checked += int(mine.sum())
    return checked


def stream_ply(path: str, vertices: int, triangles: int, parts: int,
               positions_of: Callable[[int], np.ndarray], triangles_of: Callable[[int], np.ndarray]) -> None:
    """One binary PLY of `vertices` and `triangles` streamed part by part: every part's positions (in
    output order), then every part's triangles (in output numbers), each read when written. Raises
    LimitError beyond 32-bit indices."""
    if vertices >= 2 ** 32:
        raise LimitError("%d vertices do not fit one PLY's 32-bit indices: keep the part files "
                         "(the manifest lists them)" % vertices)
    index = "int" if vertices < 2 ** 31 else "uint"
    face = np.dtype([("n", "u1"), ("v", "<i4" if index == "int" else "<u4", (3,))])
    tmp = "%s.tmp-%d" % (path, os.getpid())
    with open(tmp, "wb") as f:
        f.write(_PLY_HEADER.format(v=vertices, t=triangles, index=index).encode())
        for part in range(parts):
            f.write(positions_of(part).astype("<f8").tobytes())
        for part in range(parts):
            t = triangles_of(part)
            records = np.empty(t.shape[0], dtype=face)
            records["n"] = 3
            records["v"] = t
            f.write(records.tobytes())
    os.replace(tmp, path)


def write_ply(job: Dict[str, Any], plan: Dict[str, Any], path: str) -> None:
    """One binary PLY of the whole output, streamed block by block (vertices, then triangles), in the
    output's numbers: the bytes do not depend on the order the blocks were made in."""
    stream_ply(path, int(plan["vertices"]), int(plan["triangles"]), job["blocks"],
               lambda b: _load(block_path(job, b), ("positions",))["positions"],
               lambda b: _load(block_path(job, b), ("triangles",))["triangles"])


def write_other(job: Dict[str, Any], plan: Dict[str, Any], path: str) -> None:
    """Any other format isopatch writes (.3mf, .stl, .obj, .off, .glb, ASCII .ply by name), through one
    mesh in memory."""
    if int(plan["vertices"]) >= 2 ** 32 - 1:
        raise LimitError("the output is too large for one mesh in memory: write a .ply or keep the blocks")
    _isopatch.write_arrays(*whole_arrays(job), path)


def whole_arrays(job: Dict[str, Any]) -> Tuple[np.ndarray, np.ndarray]:
    """The job's whole output in memory, its blocks' files put together in the output's numbers:
    (positions, triangles as uint32)."""
    positions: List[np.ndarray] = []
    faces: List[np.ndarray] = []
    for block in range(job["blocks"]):
        data = _load(block_path(job, block), ("positions", "triangles"))
        positions.append(data["positions"])
        faces.append(data["triangles"].astype(np.uint32))
    return np.concatenate(positions), np.concatenate(faces)


def write_manifest(job: Dict[str, Any], plan: Dict[str, Any], summaries: Sequence[Dict[str, Any]],
                   extra: Dict[str, Any], base: Optional[str] = "") -> Dict[str, Any]:
    """The manifest: settings, blocks with counts and checksums, the output; written by renaming and
    returned with its path ("manifest"). `base` None: a run without a base file (tiles by planes)."""
    manifest = {
        "format": FORMAT,
        "version": _isopatch.__version__,
        "hash": job["hash"],
        "source": job["source"],
        "box": job["box"],
        "options": job["options"],
        "level": job["level"],
        "blocks": job["blocks"],
        "vertices": int(plan["vertices"]),
        "triangles": int(plan["triangles"]),
        "base": ({"file": os.path.basename(base_path(job)), "sha256": file_digest(base_path(job))}
                 if base is not None else None),
        "block_files": [
            dict(s, first_vertex=int(plan["first_vertex"][s["block"]]),
                 first_triangle=int(plan["first_triangle"][s["block"]]))
            for s in sorted(summaries, key=lambda s: s["block"])
        ],
    }
    manifest.update(extra)
    return write_manifest_file(job, manifest)


def write_manifest_file(job: Dict[str, Any], manifest: Dict[str, Any]) -> Dict[str, Any]:
    """Writes `manifest` as the job's manifest file (under a temporary name, renamed) and returns it with
    its path ("manifest")."""
    path = manifest_path(job)
    tmp = "%s.tmp-%d" % (path, os.getpid())
    with open(tmp, "w") as f:
        json.dump(manifest, f, indent=1, sort_keys=True)
    os.replace(tmp, path)
    return dict(manifest, manifest=path)
