#!/usr/bin/python3
"""A sampled volume meshed in blocks on Dask against one process, side by side (docs/distributed.md).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/distributed/volume.py [--size N] [--period P]
           [--tiles T] [--workers 1,2] [--window W] [--refine R] [--edge E] [--out DIR]

Writes a CT-like int16 volume of N^3 samples (a gyroid lattice of period P samples inside a sphere, scaled
to -1000..1000, level 0) as .npy, then meshes it once in one process (np.load and isopatch.mesh_volume,
all cores, in a child so that its peak memory is its own) and as T blocks on LocalClusters of each
worker count: the prefilter as a distributed pass over windows of W samples with a halo of 32, the
coefficients mapped by every task. Prints the machine and its load, then one Markdown row per run:
vertices, seconds (with the phases of a blocked run), microseconds per vertex, peak memory per process.
"""

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

import isopatch
from isopatch import distributed


def write_volume(path: str, n: int, period: float) -> None:
    """The lattice, slab by slab (no N^3 float64 temporaries)."""
    out = np.lib.format.open_memmap(path, mode="w+", dtype="<i2", shape=(n, n, n))
    axis = (np.arange(n) - (n - 1) / 2.0) * (2 * np.pi / period)
    y, z = np.meshgrid(axis, axis, indexing="ij")
    radius = axis[-1] * 0.9
    for i, x in enumerate(axis):
        g = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
        g += ((x * x + y * y + z * z) / (radius * radius)) ** 4
        out[i] = np.round(np.clip(g, -2.0, 2.0) * 500.0).astype(np.int16)
    out.flush()
    del out


def single(path: str, refine: int, edge) -> dict:
    code = ("import isopatch, numpy, resource, sys, time; t = time.perf_counter(); "
            "m = isopatch.mesh_volume(numpy.load(sys.argv[1]), 0.0, refine=%d, edge_length=%r); "
            "print(len(m.vertices), time.perf_counter() - t, "
            "resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024)") % (refine, edge)
    out = subprocess.run([sys.executable, "-c", code, path], capture_output=True, text=True, check=True)
    v, s, rss = out.stdout.split()
    return {"vertices": int(v), "seconds": float(s), "rss": int(rss)}


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--period", type=float, default=32.0)
    p.add_argument("--tiles", type=int, default=16)
    p.add_argument("--workers", default="1,2")
    p.add_argument("--window", type=int, default=192)
    p.add_argument("--refine", type=int, default=0, help="the refinement level of both (0: automatic)")
    p.add_argument("--edge", type=float, default=None, help="edge length in samples (default: automatic)")
    p.add_argument("--out", default=None)
    a = p.parse_args()
    print("machine: %d cores, load %.2f %.2f %.2f, isopatch %s" % ((os.cpu_count() or 0,) + os.getloadavg()
                                                                 + (isopatch.__version__,)))
    with tempfile.TemporaryDirectory(dir=a.out) as work:
        volume = os.path.join(work, "lattice.npy")
        write_volume(volume, a.size, a.period)
        print("volume %d^3 int16 (%.0f MB; %.0f MB of coefficients), period %g samples, window %d, %d blocks\n"
              % (a.size, os.path.getsize(volume) / 2 ** 20, 8 * a.size ** 3 / 2 ** 20, a.period, a.window,
                 a.tiles))
        print("| run | vertices | seconds | us/vertex | peak memory per process |")
        print("|---|---|---|---|---|")
        s = single(volume, a.refine, a.edge)
        print("| one process (all cores) | %d | %.1f | %.2f | %.0f MB |"
              % (s["vertices"], s["seconds"], 1e6 * s["seconds"] / s["vertices"], s["rss"] / 2 ** 20))
        sys.stdout.flush()
        for workers in [int(w) for w in a.workers.split(",")]:
            out = os.path.join(work, "blocks-%d" % workers)
            start = time.perf_counter()
            m = distributed.mesh_blocks(volume=volume, level=0.0, tiles=a.tiles, out_dir=out, workers=workers,
                                        output=os.path.join(out, "lattice.ply"), prefilter_window=a.window,
                                        refine=a.refine or None, edge_length=a.edge)
            seconds = time.perf_counter() - start
            rss = max([b["peak_rss_bytes"] for b in m["block_files"]] + [m["prefilter"]["worker_peak_rss_bytes"]])
            driver = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
            ph = m["phase_seconds"]
            print("| %d blocks, %d worker%s | %d | %.1f (cluster %.1f, prefilter %.1f, base %.1f, blocks %.1f, "
                  "merge %.1f) | %.2f | %.0f MB (driver %.0f MB) |"
                  % (a.tiles, workers, "s" if workers > 1 else "", m["vertices"], seconds, ph["cluster"],
                     ph["prefilter"], ph["base"], ph["blocks"], ph["merge"], 1e6 * seconds / m["vertices"],
                     rss / 2 ** 20, driver / 2 ** 20))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
