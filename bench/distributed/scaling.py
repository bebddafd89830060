#!/usr/bin/python3
"""Blocked meshing on Dask against one process, side by side in one run (docs/distributed.md).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/distributed/scaling.py [--surface gyroid|closed]
           [--edge E] [--radius R] [--tiles N] [--workers 1,2] [--single] [--out DIR]

Meshes a gyroid lattice (the gyroid in the box [-R, R]^3, open where the box cuts it; or, with
--surface closed, the gyroid inside a sphere of radius R closed by a smooth envelope) once in one process (isopatch.mesh, all cores; with --single) and as N blocks on LocalClusters of each
worker count (one thread per worker), and prints one Markdown row per run: vertices, seconds, microseconds
per vertex, the largest peak memory of a worker (or of the process), the share of vertices in the
band along seams, and the merged PLY's size. The machine and its load are printed first.
"""

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

import isopatch
from isopatch import distributed


GYROID = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)"


def lattice(kind: str, radius: float):
    """The formula and its box."""
    if kind == "closed":
        h = radius + 1.5
        return GYROID + "+((x^2+y^2+z^2)/%g)^4" % (radius * radius), ((-h,) * 3, (h,) * 3)
    return GYROID, ((-radius,) * 3, (radius,) * 3)


def single(formula: str, box, edge: float, refine: int) -> dict:
    """One process in a child, so that its peak memory is its own."""
    code = ("import isopatch, resource, sys, time; t = time.perf_counter(); "
            "m = isopatch.mesh(sys.argv[1], box=(%r, %r), edge_length=%r, refine=%d); "
            "print(len(m.vertices), time.perf_counter() - t, "
            "resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024)") % (box[0], box[1], edge, refine)
    out = subprocess.run([sys.executable, "-c", code, formula], capture_output=True, text=True, check=True)
    v, s, rss = out.stdout.split()
    return {"vertices": int(v), "seconds": float(s), "rss": int(rss)}


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--surface", choices=("gyroid", "closed"), default="gyroid")
    p.add_argument("--edge", type=float, default=0.1)
    p.add_argument("--radius", type=float, default=12.566)  # 4 periods per side
    p.add_argument("--tiles", type=int, default=16)
    p.add_argument("--workers", default="1,2")
    p.add_argument("--single", action="store_true")
    p.add_argument("--refine", type=int, default=0, help="the refinement level of both (0: automatic)")
    p.add_argument("--out", default=None)
    a = p.parse_args()
    formula, box = lattice(a.surface, a.radius)
    print("machine: %d cores, load %.2f %.2f %.2f, isopatch %s" % ((os.cpu_count() or 0,) + os.getloadavg()
                                                                 + (isopatch.__version__,)))
    print("%s lattice, radius %g, edge %g, refine %s, %d blocks\n"
          % (a.surface, a.radius, a.edge, a.refine or "automatic", a.tiles))
    print("| run | vertices | seconds | us/vertex | peak memory per process | seam band | PLY MB |")
    print("|---|---|---|---|---|---|---|")
    base = None
    if a.single:
        s = single(formula, box, a.edge, a.refine)
        base = s["seconds"] / s["vertices"]
        print("| one process (all cores) | %d | %.1f | %.2f | %.0f MB | - | - |"
              % (s["vertices"], s["seconds"], 1e6 * base, s["rss"] / 2 ** 20))
    for workers in [int(w) for w in a.workers.split(",")]:
        with tempfile.TemporaryDirectory(dir=a.out) as out:
            start = time.perf_counter()
            m = distributed.mesh_blocks(formula, box=box, edge_length=a.edge, tiles=a.tiles, out_dir=out,
                                        output=os.path.join(out, "lattice.ply"), workers=workers,
                                        refine=a.refine or None)
            seconds = time.perf_counter() - start
            rss = max(b["peak_rss_bytes"] for b in m["block_files"])
            size = os.path.getsize(os.path.join(out, "lattice.ply"))
            driver = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
            ph = m["phase_seconds"]
            print("| %d blocks, %d worker%s | %d | %.1f (cluster %.1f, base %.1f, blocks %.1f, merge %.1f) | %.2f "
                  "| %.0f MB (driver %.0f MB) | %.1f%% | %.0f |"
                  % (a.tiles, workers, "s" if workers > 1 else "", m["vertices"], seconds, ph["cluster"],
                     ph["base"], ph["blocks"], ph["merge"], 1e6 * seconds / m["vertices"], rss / 2 ** 20,
                     driver / 2 ** 20, 100.0 * m["seam_band_vertices"] / m["vertices"], size / 2 ** 20))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
