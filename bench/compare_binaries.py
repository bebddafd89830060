#!/usr/bin/python3
"""Two isopatch binaries side by side in one run: wall time on 1 and 2 threads at about 20k vertices.

Usage: /usr/bin/python3 bench/compare_binaries.py OLD_BINARY NEW_BINARY [--repeats N]

For each public closed surface (the edge lengths of docs/performance.md's 20k row), runs
`isopatch mesh S --edge-length H --threads T` for both binaries and both thread counts, interleaved so
that the load of a shared machine hits both alike, keeps the minimum wall time of N runs, and prints
per surface and as geometric means: each binary's 2-thread / 1-thread speed-up and the new binary's
speed over the old one. A benchmark, not a test: nothing is asserted.
"""
import argparse
import math
import os
import subprocess
import tempfile
import time

SURFACES = [("sphere", 0.02839), ("ellipsoid", 0.0208), ("torus", 0.03214), ("tanglecube", 0.08125),
            ("genus2", 0.01387), ("double_torus", 0.01537), ("chmutov6", 0.04776), ("blobby", 0.01947),
            ("cassini", 0.02237)]


def geometric_mean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    binaries = {"old": args.old, "new": args.new}
    best = {}
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "mesh.ply")
        for surface, h in SURFACES:
            for _ in range(args.repeats):
                for name, path in binaries.items():
                    for threads in (1, 2):
                        start = time.perf_counter()
                        subprocess.run([path, "mesh", surface, "--edge-length", str(h), "--threads", str(threads),
                                        "-o", out], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
                        key = (surface, name, threads)
                        best[key] = min(best.get(key, math.inf), time.perf_counter() - start)
            t = {k: best[(surface,) + k] for k in [("old", 1), ("old", 2), ("new", 1), ("new", 2)]}
            print(f"{surface:13s} old 1t {t['old', 1]:.3f} s 2t {t['old', 2]:.3f} s | new 1t {t['new', 1]:.3f} s "
                  f"2t {t['new', 2]:.3f} s | 2t/1t old {t['old', 1] / t['old', 2]:.2f} new {t['new', 1] / t['new', 2]:.2f}",
                  flush=True)
    names = [s for s, _ in SURFACES]
    for name in binaries:
        print(f"{name}: 2 threads / 1 thread (geometric mean) "
              f"{geometric_mean([best[(s, name, 1)] / best[(s, name, 2)] for s in names]):.3f}")
    for threads in (1, 2):
        print(f"new / old speed, {threads} thread(s) (geometric mean) "
              f"{geometric_mean([best[(s, 'old', threads)] / best[(s, 'new', threads)] for s in names]):.3f}")
    print(f"load average at the end: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
