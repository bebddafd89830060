#!/usr/bin/python3
"""Composite surfaces at one level against the automatic refinement level, side by side in one run.

Usage: /usr/bin/python3 bench/composite_levels.py [ISOPATCH_BINARY] [--repeats N]

For every examples/*.ipatch, at the default edge length h (the box's longest side / 64) and at h/4,
runs `isopatch mesh FILE --refine 1` and `--refine 0` (the default) alternately, keeps the least meshing
time of N runs (the tool's own `mesh.seconds`, file writing left out), and prints a markdown table:
vertices, seconds, the level reached, valence-6 share and smallest angle (`isopatch analyze`) for each.
A benchmark, not a test: nothing is asserted.
"""
import argparse
import glob
import json
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def mesh(tool, path, args, work):
    out, stats = os.path.join(work, "m.ply"), os.path.join(work, "s.json")
    subprocess.run([tool, "mesh", path, "-o", out, "-q", "--stats-json", stats] + args, check=True)
    return json.load(open(stats)), out


def analyze(tool, ply):
    return json.loads(subprocess.run([tool, "analyze", ply, "--json"], capture_output=True, text=True,
                                     check=True).stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tool", nargs="?", default=os.path.join(ROOT, "build", "bin", "isopatch"))
    parser.add_argument("--repeats", type=int, default=3)
    a = parser.parse_args()
    print("| example | edge | one level: vertices | s | valence 6 % | smallest angle | automatic: vertices | s |"
          " level | valence 6 % | smallest angle | speed-up |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for path in sorted(glob.glob(os.path.join(ROOT, "examples", "*.ipatch"))):
            name = os.path.basename(path)[:-len(".ipatch")]
            first, _ = mesh(a.tool, path, [], work)
            h = first["refine"]["target_edge"]
            for div in (1, 4):
                size = ["--edge-length", repr(h / div)]
                best = {"1": None, "0": None}
                last = {}
                for _ in range(a.repeats):
                    for level in ("1", "0"):
                        stats, ply = mesh(a.tool, path, size + ["--refine", level], work)
                        seconds = stats["mesh"]["seconds"]
                        best[level] = seconds if best[level] is None else min(best[level], seconds)
                        last[level] = (stats, analyze(a.tool, ply))
                cells = [name, "h" if div == 1 else "h/%d" % div]
                for level in ("1", "0"):
                    stats, report = last[level]
                    cells += [str(stats["mesh"]["vertices"]), "%.3f" % best[level]]
                    if level == "0":
                        cells.append(str((stats.get("refine") or {}).get("level", 1)))
                    cells += ["%.1f" % (100 * report["valence"]["share_6"]),
                              "%.1f" % report["shape"]["min_angle_degrees"]["min"]]
                cells.append("%.2f×" % (best["1"] / best["0"]))
                print("| " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
