"""The prefilter of a sampled volume as a distributed pass (isopatch.distributed, docs/distributed.md).

The tricubic B-spline that interpolates a volume's samples has coefficients that depend on every
sample of their grid line (a tridiagonal solve per line and axis; Unser, Aldroubi & Eden 1991), but
that dependence decays as z^d with the distance d, z = 2 - sqrt(3) = 0.268. A window of the volume
read with a halo of HALO samples on each side (32: 0.268^32 = 5e-19) and prefiltered on its own, with
the library's mirror boundary at its edges, gives the window's coefficients equal to the whole
volume's to rounding; at the volume's own faces the halo is cut and the mirror is the true boundary.

Every window is one task: it reads its part of the samples (a .npy file memory-mapped, so a worker
reads only those bytes), checks them, prefilters them and writes its coefficients into its region of
one .npy file of float64 coefficients, which every block task then maps instead of holding the volume.
The windows are fixed by the shape and the window size alone, so the coefficients are the same bytes
with any number of workers and any order of tasks; a task run twice writes the same values again. The
file is made under a temporary name and renamed when every window is in; a JSON file beside it keeps
the samples' range, spacing and origin, so a driver run again reuses both.
"""

import hashlib
import json
import os
import resource
import time
from typing import Any, Dict, List, Sequence, Tuple

import numpy as np

from . import _isopatch
from ._errors import InputError, IoError, NoSurfaceError

#: Samples of halo on each side of a window (the library's kPrefilterHalo).
HALO = int(_isopatch.PREFILTER_HALO)
#: Samples along each side of a window: 192 + 2 x 32 = 256, 134 MB of doubles read per task.
DEFAULT_WINDOW = 192

Window = Tuple[Tuple[int, int], Tuple[int, int], Tuple[int, int]]


def plan_windows(shape: Sequence[int], window: int) -> List[Window]:
    """The windows of a volume of `shape`: [lo, hi) per axis, every side `window` samples but the last
    one of each axis, in C order."""
    if not isinstance(window, int) or window < 2:
        raise InputError("the prefilter window must be a whole number of at least 2 samples", "prefilter_window")
    axes = [[(lo, min(lo + window, int(n))) for lo in range(0, int(n), window)] for n in shape]
    return [(a, b, c) for a in axes[0] for b in axes[1] for c in axes[2]]


_SAMPLES: Dict[Tuple[Any, ...], np.ndarray] = {}


def _samples(path: str) -> np.ndarray:
    """The samples of a .npy file, memory-mapped (one mapping per process and file: a file replaced at
    the same path is mapped again)."""
    try:
        info = os.stat(path)
    except OSError as e:
        raise IoError("%s: cannot open: %s" % (path, e.strerror)) from None
    key = (path, info.st_ino, info.st_size, info.st_mtime_ns)
    array = _SAMPLES.get(key)
    if array is None:
        try:
            array = np.load(path, mmap_mode="r", allow_pickle=False)
        except (OSError, ValueError) as e:
            raise IoError("%s: %s" % (path, e)) from None
        if array.ndim != 3:
            raise IoError("%s: the array has %d dimensions; a volume needs 3" % (path, array.ndim))
        if array.dtype.kind not in "biuf" or array.dtype.itemsize > 8:
            raise IoError("%s: unsupported dtype %s (want bool, an integer, float32 or float64)"
                          % (path, array.dtype.str))
        if min(array.shape) < 2:
            raise IoError("%s: the array is %s: every side needs at least 2 samples"
                          % (path, " x ".join(str(n) for n in array.shape)))
        _SAMPLES.clear()
        _SAMPLES[key] = array
    return array


def prefilter_window(pass_: Dict[str, Any], index: int) -> Dict[str, Any]:
    """Prefilters window `index` of the pass with its halo and writes its coefficients into the pass's
    temporary file. Returns the range of the window's own samples and the worker's peak memory.
    Raises InputError for a NaN or infinite sample (naming its index). Idempotent."""
    samples = _samples(pass_["samples"])
    window = pass_["windows"][index]
    shape = samples.shape
    read = [(max(0, lo - HALO), min(int(n), hi + HALO)) for (lo, hi), n in zip(window, shape)]
    block = np.array(samples[tuple(slice(lo, hi) for lo, hi in read)], dtype=np.float64, order="C")
    own = tuple(slice(lo - r[0], hi - r[0]) for (lo, hi), r in zip(window, read))
    # Checked in the window's own samples: each bad sample is reported by the one window that owns it.
    bad = ~np.isfinite(block[own])
    if bad.any():
        first = np.argwhere(bad)[0]
        where = tuple(int(i) + lo for i, (lo, _) in zip(first, window))
        kind = "NaN" if np.isnan(block[own][tuple(first)]) else "an infinity"
        raise InputError("the volume has %s at index %s" % (kind, where), "volume")
    lowest, highest = float(block[own].min()), float(block[own].max())
    _isopatch.prefilter(block)
    _write_window(pass_["part"], pass_["offset"], shape, window, block[own])
    return {"window": index, "min": lowest, "max": highest,
            "peak_rss_bytes": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024}


def _write_window(path: str, offset: int, shape: Sequence[int], window: Window, values: np.ndarray) -> None:
    """Writes `values` into their window of the C-order float64 array at byte `offset` of `path`, one
    run along the last axis at a time (pwrite, not a mapping: the pages written do not count as this
    worker's memory)."""
    (i0, i1), (j0, j1), (k0, k1) = window
    n1, n2 = int(shape[1]), int(shape[2])
    rows = np.ascontiguousarray(values, dtype="<f8")
    with open(path, "r+b") as f:
        for i in range(i0, i1):
            if k0 == 0 and k1 == n2:  # whole rows: the window's plane at i is one run of the file
                os.pwrite(f.fileno(), rows[i - i0].tobytes(), offset + 8 * (i * n1 + j0) * n2)
                continue
            for j in range(j0, j1):
                os.pwrite(f.fileno(), rows[i - i0, j - j0].tobytes(), offset + 8 * ((i * n1 + j) * n2 + k0))


def _digest(described: Dict[str, Any]) -> str:
    return hashlib.sha256(json.dumps(described, sort_keys=True).encode()).hexdigest()[:16]


def coefficients(client: Any, volume: str, digest: str, level: float, window: int, out_dir: str) -> Dict[str, Any]:
    """The coefficients of `volume` (a .npy or .nrrd file whose bytes hash to `digest`) in `out_dir`:
    made by a distributed pass over windows of `window` samples, or found made. A .nrrd file is read
    once by this process and kept as a .npy of samples for the windows to read.

    Returns {"coefficients": path, "spacing", "origin", "min", "max", "window", "seconds", "reused"}.
    Raises IoError for an unreadable volume, InputError for a NaN sample, NoSurfaceError when no
    sample crosses `level`."""
    start = time.perf_counter()
    name = _digest({"volume": digest, "window": window, "halo": HALO, "version": _isopatch.__version__})
    final = os.path.join(out_dir, "coefficients-%s.npy" % name)
    facts_path = os.path.join(out_dir, "coefficients-%s.json" % name)
    facts: Dict[str, Any] = {}
    if os.path.exists(final) and os.path.exists(facts_path):
        with open(facts_path) as f:
            facts = json.load(f)
        facts["reused"] = True
    else:
        samples, spacing, origin = _samples_file(volume, digest, out_dir)
        shape = _samples(samples).shape
        windows = plan_windows(shape, window)
        part = "%s.part-%d-%d" % (final, os.getpid(), time.monotonic_ns())
        created = np.lib.format.open_memmap(part, mode="w+", dtype="<f8", shape=tuple(int(n) for n in shape))
        job = {"samples": samples, "windows": windows, "part": part, "offset": int(created.offset)}
        del created
        try:
            futures = client.map(prefilter_window, [job] * len(windows), range(len(windows)), pure=False)
            ranges = client.gather(futures)
        except BaseException:
            os.remove(part)
            raise
        facts = {"spacing": list(spacing), "origin": list(origin), "shape": [int(n) for n in shape],
                 "min": min(r["min"] for r in ranges), "max": max(r["max"] for r in ranges),
                 "window": window, "halo": HALO, "windows": len(windows),
                 "worker_peak_rss_bytes": max(r["peak_rss_bytes"] for r in ranges)}
        os.replace(part, final)
        tmp = "%s.tmp-%d" % (facts_path, os.getpid())
        with open(tmp, "w") as f:
            json.dump(facts, f, indent=1, sort_keys=True)
        os.replace(tmp, facts_path)
        facts["reused"] = False
    if not (facts["min"] < level <= facts["max"]):
        raise NoSurfaceError("no sample of the volume crosses level %g (the samples range over [%g, %g])"
                             % (level, facts["min"], facts["max"]))
    facts["coefficients"] = final
    facts["seconds"] = time.perf_counter() - start
    return facts


def _samples_file(volume: str, digest: str, out_dir: str) -> Tuple[str, Sequence[float], Sequence[float]]:
    """A .npy file of the samples the windows read, with the spacing and origin: the .npy itself, or
    for a .nrrd file a .npy written once from it."""
    if volume.lower().endswith(".npy"):
        _samples(volume)  # checked here, before any task runs
        return volume, (1.0, 1.0, 1.0), (0.0, 0.0, 0.0)
    array, spacing, origin = _isopatch.read_volume(volume)
    path = os.path.join(out_dir, "samples-%s.npy" % digest[:16])
    if not os.path.exists(path):
        tmp = "%s.tmp-%d" % (path, os.getpid())
        with open(tmp, "wb") as f:
            np.save(f, np.ascontiguousarray(array, dtype=np.float64))
        os.replace(tmp, path)
    return path, tuple(spacing), tuple(origin)
