#!/usr/bin/python3
"""A capped gyroid lattice meshed as blocks on Dask against one process, side by side in one run, each the
whole command-line process timed from outside (docs/distributed.md, "A capped lattice of twelve million
vertices").

Usage: /usr/bin/python3 bench/distributed/capped.py ISOPATCH [--periods P] [--edge E] [--tiles N]
           [--workers W] [--out DIR] [--3mf]

ISOPATCH is the command-line tool (build/bin/isopatch). The part is the gyroid capped by [-P pi, P pi]^3;
the defaults (P = 4, edge 0.0316, 64 tiles, 2 workers) make about twelve million vertices and need about
8 GB on the driver and in one process. Prints the machine's load, then one Markdown row per run: vertices,
seconds (whole process), the stages (one process: its --stats-json; blocks: the manifest's phases) and
peak memory (the process; for blocks also the largest worker's). With --3mf the blocked run writes a 3MF
and PrusaSlicer's report of it is printed (manifold, parts, facets).
"""

import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

GYROID = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)"


def timed(command):
    """Runs `command` under /usr/bin/time; (seconds, peak KB, stdout)."""
    start = time.perf_counter()
    run = subprocess.run(["/usr/bin/time", "-f", "PEAK %M"] + command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if run.returncode != 0:
        sys.exit("failed: %s\n%s" % (" ".join(command), run.stderr[-2000:]))
    peak = int(re.search(r"PEAK (\d+)", run.stderr).group(1))
    return seconds, peak, run.stdout


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("isopatch")
    p.add_argument("--periods", type=int, default=4)
    p.add_argument("--edge", type=float, default=0.0316)
    p.add_argument("--tiles", type=int, default=64)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--out", default=None)
    p.add_argument("--3mf", dest="three_mf", action="store_true")
    a = p.parse_args()
    out = a.out or tempfile.mkdtemp(prefix="isopatch-capped-")
    half = a.periods * 3.141592653589793
    formula = "max(%s,max(max(abs(x),abs(y)),abs(z))-%d*pi)" % (GYROID, a.periods)
    box = ",".join(["%.4f" % -(half + 0.134)] * 3 + ["%.4f" % (half + 0.134)] * 3)
    print("machine: %d cores, load %s" % (os.cpu_count(), open("/proc/loadavg").read().split()[:3]))
    print("| run | vertices | seconds | stages | peak memory |")
    print("|---|---|---|---|---|")
    blocks_dir = os.path.join(out, "blocks")
    shutil.rmtree(blocks_dir, ignore_errors=True)
    output = os.path.join(out, "blocked." + ("3mf" if a.three_mf else "ply"))
    seconds, peak, _ = timed([a.isopatch, "mesh", formula, "--box", box, "--edge-length", str(a.edge), "--tiles",
                              str(a.tiles), "--workers", str(a.workers), "--out-dir", blocks_dir, "-o", output])
    manifest = json.load(open(glob.glob(os.path.join(blocks_dir, "manifest-*.json"))[0]))
    worker = max(b["peak_rss_bytes"] for c in manifest["cuts"] for b in c["block_files"])
    stages = ", ".join("%s %.1f" % (k, v) for k, v in manifest["phase_seconds"].items())
    print("| %d blocks, %d workers | %d | %.1f | %s | driver %d MB, worker %d MB |"
          % (a.tiles, a.workers, manifest["vertices"], seconds, stages, peak >> 10, worker >> 20))
    stats = os.path.join(out, "one.json")
    seconds, peak, _ = timed([a.isopatch, "mesh", formula, "--box", box, "--edge-length", str(a.edge), "-o",
                              os.path.join(out, "one.ply"), "--stats-json", stats])
    s = json.load(open(stats))
    print("| one process | %d | %.1f | meshing %.1f (caps %.1f) | %d MB |"
          % (s["mesh"]["vertices"], seconds, s["mesh"]["seconds"], s["creases"]["seconds"], peak >> 10))
    if a.three_mf:
        info = subprocess.run(["prusa-slicer", "--info", output], capture_output=True, text=True)
        print("prusa-slicer:", dict(re.findall(r"^(\w+) = *(\S+)$", info.stdout, re.M)))


if __name__ == "__main__":
    main()
