#!/usr/bin/python3
"""Composites (.ipatch) and a formula with exact creases meshed in blocks on Dask against one process,
side by side (docs/distributed.md, "Composites" and "Formulas with exact creases").

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/distributed/composites.py --isopatch build/bin/isopatch
           [--workers 2] [--out DIR]

For each case: the blocked run (LocalCluster of one-thread workers on 127.0.0.1) and the command line in
one process, both measured by `isopatch analyze --surface` (the composite's patches, or the formula).
Prints the machine and its load, then one Markdown row per case: level, vertices, valence 6, smallest
angle, largest vertex distance, watertight, seconds (blocked, one process).
"""

import argparse
import json
import os
import platform
import subprocess
import tempfile
import time

from isopatch import distributed

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")
# (name, surface, box or None, edge, refine (0: automatic), blocks)
CASES = [
    ("rounded_box.ipatch", os.path.join(EXAMPLES, "rounded_box.ipatch"), None, 0.04, 0, 6),
    ("cube.ipatch", os.path.join(EXAMPLES, "cube.ipatch"), None, 0.03, 0, 8),
    ("icosahedron_blend.ipatch", os.path.join(EXAMPLES, "icosahedron_blend.ipatch"), None, 0.03, 0, 8),
    ("box minus cylinder (CSG)", "max(max(max(abs(x),abs(y)),abs(z))-1,0.25-x^2-y^2)",
     ((-1.5, -1.5, -1.5), (1.5, 1.5, 1.5)), 0.03, 0, 8),
]


def analyze(isopatch, path, surface, box):
    cmd = [isopatch, "analyze", path, "--surface", surface, "--json"]
    if box:
        cmd += ["--box", ",".join(str(v) for v in box[0] + box[1])]
    d = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    return (d["topology"]["vertices"], d["valence"]["share_6"], d["shape"]["min_angle_degrees"]["min"],
            d["accuracy"]["vertex_distance"]["max"], d["topology"]["watertight"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--isopatch", required=True)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    out = args.out or tempfile.mkdtemp(prefix="isopatch-composites-")
    print("machine: %s, %d cores, load %s" % (platform.processor() or platform.machine(), os.cpu_count(),
                                                " ".join("%.2f" % v for v in os.getloadavg())))
    print("| case | blocks | level | vertices (one process) | valence 6 | smallest angle | largest distance "
          "| watertight | seconds: blocks, one process |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, surface, box, edge, refine, blocks in CASES:
        tag = name.split()[0].replace(".ipatch", "")
        options = {"edge_length": edge}
        if refine:
            options["refine"] = refine
        start = time.perf_counter()
        manifest = distributed.mesh_blocks(surface, box=box, tiles=blocks, out_dir=os.path.join(out, tag),
                                           output=os.path.join(out, tag + "-blocks.ply"), workers=args.workers,
                                           **options)
        blocked_seconds = time.perf_counter() - start
        cmd = [args.isopatch, "mesh", surface, "--edge-length", str(edge), "-o", os.path.join(out, tag + "-one.ply")]
        if box:
            cmd += ["--box", ",".join(str(v) for v in box[0] + box[1])]
        if refine:
            cmd += ["--refine", str(refine)]
        start = time.perf_counter()
        subprocess.run(cmd, check=True, capture_output=True)
        one_seconds = time.perf_counter() - start
        b = analyze(args.isopatch, os.path.join(out, tag + "-blocks.ply"), surface, box)
        o = analyze(args.isopatch, os.path.join(out, tag + "-one.ply"), surface, box)
        print("| %s | %d | %d | %d (%d) | %.2f%% (%.2f%%) | %.2f (%.2f) | %.1e (%.1e) | %s (%s) | %.1f, %.1f |" % (
            name, blocks, manifest["level"], b[0], o[0], 100 * b[1], 100 * o[1], b[2], o[2], b[3], o[3],
            "yes" if b[4] else "no", "yes" if o[4] else "no", blocked_seconds, one_seconds), flush=True)


if __name__ == "__main__":
    main()
