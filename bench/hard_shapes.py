#!/usr/bin/python3
"""Meshes the shapes that break the quality floor most easily and prints one table row per case.

Open surfaces cut by boxes and planes at grazing angles, thin rims (ellipsoids with small axis ratios)
and singular surfaces, at the default settings (no flag), as a new user would mesh them. For every mesh:
vertices, time, smallest angle, share of interior vertices of valence 6, H nRMS, and for open surfaces
whether every boundary vertex lies on a face of the box or a plane of the region (to 1e-9 of the
diagonal) and on f = 0 (the analyser's largest vertex distance).

Corners of the cut whose wedge (the angle between the two cut curves meeting on a box edge) is under
20 degrees cap the smallest angle there whatever the mesh: the table gives the smallest angle away from
them too, and the smallest wedge.

Usage: /usr/bin/python3 bench/hard_shapes.py [--bin build/bin/isopatch] [--out DIR] [--only SUBSTRING]
                                           [--random N] [--json FILE]
"""

import argparse
import collections
import json
import math
import os
import random
import struct
import subprocess
import sys
import time


GYROID = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)"
SCHWARZ_P = "cos(x)+cos(y)+cos(z)"
SCHWARZ_D = "sin(x)*sin(y)*sin(z)+sin(x)*cos(y)*cos(z)+cos(x)*sin(y)*cos(z)+cos(x)*cos(y)*sin(z)"
SPHERE = "x^2+y^2+z^2-1"
TORUS = "(x^2+y^2+z^2+1-0.16)^2-4*(x^2+y^2)"


def cube(a, b=None):
    b = a if b is None else b
    return f"{-a},{-a},{-a},{b},{b},{b}"


def ellipsoid(b, c):
    """Semi-axes 1, b, c scaled so the longest is 4 (the issue's 4 x 1 x 0.05 is b = 0.25, c = 0.0125)."""
    return f"x^2/16+y^2/{(4 * b) ** 2:g}+z^2/{(4 * c) ** 2:g}-1", cube(4.2)


# (group, name, formula, box, region or None)
CASES = [
    ("grazing box", "gyroid ±3.1", GYROID, cube(3.1), None),
    ("grazing box", "gyroid ±3.0", GYROID, cube(3.0), None),
    ("grazing box", "gyroid ±2.35", GYROID, cube(2.35), None),
    ("grazing box", "gyroid −1.6..2.9", GYROID, cube(1.6, 2.9), None),
    ("grazing box", "gyroid skew box", GYROID, "-3.05,-2.2,-1.55,2.95,3.3,2.6", None),
    ("grazing box", "Schwarz P ±3.1", SCHWARZ_P, cube(3.1), None),
    ("grazing box", "Schwarz P −2.13..2.27", SCHWARZ_P, "-2.128,-1.742,-1.814,1.937,2.097,2.271", None),
    ("grazing box", "Schwarz P −1.55..4.75", SCHWARZ_P, cube(1.55, 4.75), None),
    ("grazing box", "Schwarz D ±3.1", SCHWARZ_D, cube(3.1), None),
    ("grazing box", "Schwarz D ±1.5", SCHWARZ_D, cube(1.5), None),
    ("grazing box", "Schwarz D −0.8..2.3", SCHWARZ_D, cube(0.8, 2.3), None),
    ("grazing plane", "sphere z ≤ 0.98", SPHERE, cube(1.2), "0,0,1,-0.98"),
    ("grazing plane", "sphere tilted ≤ 0.995", SPHERE, cube(1.2), "0.267261,0.534522,0.801784,-0.995"),
    ("grazing plane", "sphere two planes", SPHERE, cube(1.2), "0,0,1,-0.97;0.6,0,0.8,-0.985"),
    ("grazing plane", "sphere z ≤ 0.9999 (hole r 0.014)", SPHERE, cube(1.2), "0,0,1,-0.9999"),
    ("grazing plane", "torus z ≤ 0.39", TORUS, "-1.6,-1.6,-0.6,1.6,1.6,0.6", "0,0,1,-0.39"),
    ("grazing plane", "torus x ≤ 1.39", TORUS, "-1.6,-1.6,-0.6,1.6,1.6,0.6", "1,0,0,-1.39"),
    ("grazing plane", "torus x ≥ -0.61 (inner)", TORUS, "-1.6,-1.6,-0.6,1.6,1.6,0.6", "-1,0,0,-0.61"),
    ("grazing plane", "torus z ≤ 0.3999 (slit 0.018)", TORUS, "-1.6,-1.6,-0.6,1.6,1.6,0.6", "0,0,1,-0.3999"),
]
for b, c in [(0.5, 0.1), (0.25, 0.05), (0.25, 0.025), (0.25, 0.0125)]:
    f, box = ellipsoid(b, c)
    CASES.append(("thin rim", f"ellipsoid 1:{b:g}:{c:g}", f, box, None))
CASES += [
    ("singular", "heart", "heart", None, None),
    ("singular", "Klein bottle",
     "(x^2+y^2+z^2+2*y-1)*((x^2+y^2+z^2-2*y-1)^2-8*z^2)+16*x*z*(x^2+y^2+z^2-2*y-1)", cube(3.2), None),
    ("singular", "Barth sextic",
     "p=(1+sqrt(5))/2; 4*(p^2*x^2-y^2)*(p^2*y^2-z^2)*(p^2*z^2-x^2)-(1+2*p)*(x^2+y^2+z^2-1)^2", cube(1.9), None),
    ("singular", "a decic with Barth's factors",
     "p=(1+sqrt(5))/2; (x^2-p^4*y^2)*(y^2-p^4*z^2)*(z^2-p^4*x^2)*(x^4+y^4+z^4-2*x^2*y^2-2*x^2*z^2-2*y^2*z^2)"
     "-(1+2*p)/4*(x^2+y^2+z^2-1)^2", cube(1.9), None),
]


def read_ply(path):
    """Positions and triangles of a binary little-endian PLY as written by isopatch (standard library only)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    nv = nf = 0
    props = []
    cur = None
    for line in data[:end].decode().splitlines():
        p = line.split()
        if p[:2] == ["element", "vertex"]:
            nv, cur = int(p[2]), "v"
        elif p[:2] == ["element", "face"]:
            nf, cur = int(p[2]), "f"
        elif p and p[0] == "property" and cur == "v":
            props.append((p[2], {"double": "d", "float": "f", "uchar": "B", "int": "i"}[p[1]]))
    vfmt = "<" + "".join(t for _, t in props)
    vsize = struct.calcsize(vfmt)
    ix = [n for n, _ in props].index("x")
    points = [struct.unpack_from(vfmt, data, end + k * vsize)[ix:ix + 3] for k in range(nv)]
    off = end + nv * vsize
    tris = [struct.unpack_from("<3i", data, off + k * 13 + 1) for k in range(nf)]
    return points, tris


def boundary_off_cut(points, tris, box, region):
    """Largest distance of a boundary vertex to the nearest box face or region plane, or None (closed)."""
    uses = collections.Counter()
    for t in tris:
        for i in range(3):
            a, b = t[i], t[(i + 1) % 3]
            uses[(min(a, b), max(a, b))] += 1
    boundary = {v for edge, n in uses.items() if n == 1 for v in edge}
    if not boundary:
        return None
    planes = []
    for plane in (region.split(";") if region else []):
        a = [float(s) for s in plane.split(",")]
        n = math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)
        planes.append([c / n for c in a])
    worst = 0.0
    for v in boundary:
        p = points[v]
        d = min(min(abs(p[k] - box[k]), abs(p[k] - box[k + 3])) for k in range(3))
        for a in planes:
            d = min(d, abs(a[0] * p[0] + a[1] * p[1] + a[2] * p[2] + a[3]))
        worst = max(worst, d)
    return worst


def angle_at(p, q, r):
    """The angle at p of triangle p q r, degrees."""
    u = [q[k] - p[k] for k in range(3)]
    w = [r[k] - p[k] for k in range(3)]
    nu, nw = math.sqrt(sum(c * c for c in u)), math.sqrt(sum(c * c for c in w))
    if nu == 0.0 or nw == 0.0:
        return 0.0
    return math.degrees(math.acos(max(-1.0, min(1.0, sum(u[k] * w[k] for k in range(3)) / (nu * nw)))))


def corner_wedges(points, tris, box):
    """(smallest wedge of a cut corner, smallest angle of the triangles not at a corner whose wedge is under
    20 degrees). A corner is a vertex on two box faces; its wedge, the angle between the two cut curves
    there, is the sum of its triangles' angles at it: no mesh has a smaller largest angle at it than that
    wedge split in as few triangles as possible."""
    def faces(p):
        return sum(1 for k in range(3) if p[k] == box[k] or p[k] == box[k + 3])
    wedge = collections.defaultdict(float)
    corners = {v for v, p in enumerate(points) if faces(p) >= 2}
    for t in tris:
        for i in range(3):
            if t[i] in corners:
                wedge[t[i]] += angle_at(points[t[i]], points[t[(i + 1) % 3]], points[t[(i + 2) % 3]])
    narrow = {v for v, a in wedge.items() if a < 20.0}
    smallest = 180.0
    for t in tris:
        if narrow.intersection(t):
            continue
        p = [points[v] for v in t]
        smallest = min(smallest, angle_at(p[0], p[1], p[2]), angle_at(p[1], p[2], p[0]), angle_at(p[2], p[0], p[1]))
    return (min(wedge.values()) if wedge else None), smallest, len(narrow)


def run(tool, case, out):
    group, name, formula, box, region = case
    args = [tool, "mesh", formula, "-o", out, "--stats-json", out + ".json"]
    if box:
        args += ["--box", box]
    if region:
        args += ["--region", region]
    t = time.time()
    p = subprocess.run(args, capture_output=True, text=True, timeout=900)
    seconds = time.time() - t
    row = {"group": group, "name": name, "formula": formula, "box": box, "region": region, "seconds": seconds,
           "exit": p.returncode, "warnings": [l for l in p.stderr.splitlines() if l.startswith("warning")]}
    if p.returncode != 0:
        row["error"] = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "no message"
        return row
    a = [tool, "analyze", out, "--json", "--surface", formula] + (["--box", box] if box else [])
    q = subprocess.run(a, capture_output=True, text=True, timeout=900)
    d = json.loads(q.stdout)
    row["vertices"] = d["mesh"]["vertices"]
    row["min_angle"] = d["shape"]["min_angle_degrees"]["min"]
    row["valence6"] = d["valence"]["share_6"]
    row["h_nrms"] = d.get("accuracy", {}).get("mean_curvature", {}).get("nrms")
    row["vertex_distance"] = d.get("accuracy", {}).get("vertex_distance", {}).get("max")
    away = d.get("away_from_singular_points")
    row["min_angle_away_singular"] = away["min_angle_degrees"] if away else None
    stats = json.load(open(out + ".json"))
    found = stats.get("singular_points", {})
    row["singular"] = (f"{found.get('points', 0)} points, {found.get('curves', 0)} curves"
                       if found.get("points") or found.get("curves") else None)
    if box:
        pts, tris = read_ply(out)
        corners = [float(s) for s in box.split(",")]
        row["boundary_off_cut"] = boundary_off_cut(pts, tris, corners, region)
        row["smallest_wedge"], row["min_angle_off_narrow_corners"], row["narrow_corners"] = corner_wedges(pts, tris, corners)
    return row


def random_boxes(seed, count):
    """`count` boxes drawn with a fixed seed for the three triply periodic surfaces in turn: corners in
    [-3.5, -1] and [1, 3.5] on every axis, so their faces cut the surfaces at arbitrary phases."""
    rng = random.Random(seed)
    out = []
    for k in range(count):
        name, formula = [("gyroid", GYROID), ("Schwarz P", SCHWARZ_P), ("Schwarz D", SCHWARZ_D)][k % 3]
        lo = [rng.uniform(-3.5, -1.0) for _ in range(3)]
        hi = [rng.uniform(1.0, 3.5) for _ in range(3)]
        box = ",".join(f"{v:.3f}" for v in lo + hi)
        out.append(("random box", f"{name} {box}", formula, box, None))
    return out


def fmt(x, spec):
    return "–" if x is None else format(x, spec)


HEADER = ["| group | case | vertices | s | smallest angle | away from narrow corners | smallest corner wedge | "
          "valence 6 % | H nRMS | boundary off cut | singular points | away from them |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|"]


def row_line(r):
    if "error" in r:
        return f"| {r['group']} | {r['name']} | failed: {r['error']} ||||||||||"
    return (f"| {r['group']} | {r['name']} | {r['vertices']} | {r['seconds']:.2f} | {r['min_angle']:.2f} | "
            f"{fmt(r.get('min_angle_off_narrow_corners'), '.2f')} | {fmt(r.get('smallest_wedge'), '.1f')} | "
            f"{100 * r['valence6']:.1f} | {fmt(r['h_nrms'], '.3g')} | {fmt(r.get('boundary_off_cut'), '.1e')} | "
            f"{r.get('singular') or '–'} | {fmt(r.get('min_angle_away_singular'), '.2f')} |")


def section(rows, command):
    """The Markdown section of docs/quality.md for these rows."""
    random_rows = [r for r in rows if r["group"] == "random box" and "error" not in r]
    held = sum(1 for r in random_rows if r["min_angle"] >= 20.0)
    away = sum(1 for r in random_rows if (r.get("min_angle_off_narrow_corners") or 0.0) >= 20.0)
    lines = [
        "## Shapes that break the floor most easily",
        "",
        f"Measured by `{command}` at the default settings (no flag), as a new user would mesh them: "
        "triply periodic surfaces cut by boxes whose faces and edges meet them at every angle (named "
        "boxes and boxes drawn at random with a fixed seed), a sphere and a torus cut by planes nearly "
        "tangent to them, ellipsoids with thin rims, and surfaces with singular points. *Away from narrow "
        "corners* leaves out the triangles at a corner of the cut (a vertex on two box faces) whose wedge, "
        "the angle between the two cut curves there, is under 20 degrees: no mesh has a larger smallest "
        "angle there. *Boundary off cut* is the largest distance of a boundary vertex from the nearest box "
        "face or region plane. *Away from them* is the smallest angle outside balls of two mean edge "
        "lengths around the singular points that `isopatch mesh` found and listed.",
        "",
    ] + HEADER + [row_line(r) for r in rows] + [
        "",
        f"Random boxes: {held} of {len(random_rows)} hold a smallest angle of 20 degrees, {away} away from "
        "narrow corners.",
        "",
    ]
    return "\n".join(lines)


def run_all(tool, work, only="", random_count=12, seed=35, log=None):
    """Meshes every case (and the random boxes) into `work`; returns the rows."""
    os.makedirs(work, exist_ok=True)
    rows = []
    for i, case in enumerate(CASES + random_boxes(seed, random_count)):
        if only and only not in case[0] + " " + case[1]:
            continue
        r = run(tool, case, os.path.join(work, f"case{i:02d}.ply"))
        rows.append(r)
        if log:
            log(r)
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/bin/isopatch")
    ap.add_argument("--out", default="out/hard_shapes")
    ap.add_argument("--only", default="")
    ap.add_argument("--random", type=int, default=12, help="boxes drawn at random (fixed seed) for the TPMS")
    ap.add_argument("--json")
    args = ap.parse_args()
    print("\n".join(HEADER))

    def log(r):
        print(row_line(r), flush=True)
        for w in r.get("warnings", []):
            print(f"    {w}", file=sys.stderr)
    rows = run_all(args.bin, args.out, args.only, args.random, log=log)
    if args.json:
        json.dump(rows, open(args.json, "w"), indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
