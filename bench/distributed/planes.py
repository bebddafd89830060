#!/usr/bin/python3
"""Tiles by planes against blocks of one base and one process, side by side (docs/distributed.md,
"Tiles by planes").

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/distributed/planes.py --isopatch build/bin/isopatch
           [--periods 4] [--edge 0.1] [--refine 4] [--tiles 8] [--workers 2] [--out DIR]

The gyroid in the box [-periods*pi, periods*pi]^3 (open where the box cuts it) meshed three ways in one
run: one process (the command line, both cores), blocks of one base and tiles by planes (each a
LocalCluster of one-thread workers on 127.0.0.1, the cluster's start included). Each mesh is measured by
`isopatch analyze --surface`; the tiled one also apart within one base edge of its inner planes (the
seam band) and off it. Prints the machine and its load, then one Markdown row per run.
"""

import argparse
import json
import math
import os
import platform
import subprocess
import tempfile
import time

import numpy as np

from isopatch import distributed
from isopatch._tiles import seam_band_angles

GYROID = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)"


def analyze(isopatch, path, box):
    cmd = [isopatch, "analyze", path, "--surface", GYROID, "--json", "--box", ",".join(str(v) for v in box)]
    return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    v = int(header.split("element vertex ")[1].split()[0])
    t = int(header.split("element face ")[1].split()[0])
    vertices = np.frombuffer(data, dtype="<f8", count=3 * v, offset=end).reshape(v, 3)
    faces = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("v", "<i4", (3,))]), count=t, offset=end + 24 * v)
    return vertices, faces["v"].astype(np.int64)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--isopatch", required=True)
    ap.add_argument("--periods", type=float, default=4.0)
    ap.add_argument("--edge", type=float, default=0.1)
    ap.add_argument("--refine", type=int, default=4)
    ap.add_argument("--tiles", type=int, default=8)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    out = a.out or tempfile.mkdtemp(prefix="isopatch-planes-")
    half = a.periods * math.pi
    box = (-half, -half, -half, half, half, half)
    print("machine: %s, %d cores, load %s" % (platform.processor() or platform.machine(), os.cpu_count(),
                                                " ".join("%.2f" % v for v in os.getloadavg())))
    print("gyroid, box [-%g, %g]^3, edge %g, refine %d, %d tiles or blocks, %d workers\n"
          % (half, half, a.edge, a.refine, a.tiles, a.workers))
    print("| run | vertices | seconds | µs per vertex | valence 6 | smallest angle | off / on the seam band "
          "| band's share | largest distance | Euler characteristic |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    runs = []
    start = time.perf_counter()
    one = os.path.join(out, "one.ply")
    subprocess.run([a.isopatch, "mesh", GYROID, "--box", ",".join(str(v) for v in box), "--edge-length",
                    str(a.edge), "--refine", str(a.refine), "-o", one], check=True, capture_output=True)
    runs.append(("one process", one, time.perf_counter() - start, None))
    for split in ("blocks", "planes"):
        start = time.perf_counter()
        path = os.path.join(out, split + ".ply")
        manifest = distributed.mesh_blocks(GYROID, box=(box[:3], box[3:]), edge_length=a.edge, refine=a.refine,
                                           tiles=a.tiles, out_dir=os.path.join(out, split), output=path,
                                           workers=a.workers, split=split)
        runs.append(("%s (%d)" % ("tiles by planes" if split == "planes" else "blocks of one base",
                                  manifest["blocks"]), path, time.perf_counter() - start, manifest))
    for name, path, seconds, manifest in runs:
        d = analyze(a.isopatch, path, box)
        vertices = d["topology"]["vertices"]
        band = "-"
        share = "-"
        if manifest is not None and manifest.get("split") == "planes":
            on, off, fraction = seam_band_angles(*read_ply(path), manifest["planes"], a.edge * manifest["level"])
            band = "%.2f / %.2f" % (off, on)
            share = "%.1f%%" % (100 * fraction)
        print("| %s | %d | %.1f | %.2f | %.2f%% | %.2f | %s | %s | %.1e | %d |" % (
            name, vertices, seconds, 1e6 * seconds / vertices, 100 * d["valence"]["share_6"],
            d["shape"]["min_angle_degrees"]["min"], band, share, d["accuracy"]["vertex_distance"]["max"],
            d["topology"]["euler_characteristic"]), flush=True)


if __name__ == "__main__":
    main()
