#!/usr/bin/env python3
"""Smoke test of isopatch_dual_contouring (bench/dual_contouring/; Ju, Losasso, Schaefer & Warren,
"Dual contouring of Hermite data", SIGGRAPH 2002) on the cube max(|x|, |y|, |z|) = 1.

Runs the tool with --cells 16 in the box -1.5..1.5 (cells of 3/16: the cube's faces and corners fall
inside cells, never on their faces) and checks that the mesh is closed and consistently oriented
(every edge in two triangles, once in each direction), has Euler characteristic 2, encloses a volume
within 2% of 8 (positive: triangles face outwards) and reproduces the cube's 8 corners (the QEF of
a corner cell has three independent planes: the vertex nearest each corner lies within 1e-6 of it).

Usage: check_dual_contouring_cube.py TOOL OUTPUT_DIR
"""
import itertools
import os
import subprocess
import sys


def read_obj(path):
    positions, triangles = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                positions.append(tuple(float(c) for c in parts[1:4]))
            elif parts[0] == "f":
                corners = [int(c.split("/")[0]) - 1 for c in parts[1:]]
                if len(corners) != 3:
                    raise ValueError("not a triangle: " + line.strip())
                triangles.append(tuple(corners))
    return positions, triangles


def signed_volume(positions, triangles):
    volume = 0.0
    for a, b, c in triangles:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = positions[a], positions[b], positions[c]
        volume += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return volume / 6.0


def main():
    tool, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    mesh_path = os.path.join(out_dir, "dc_cube.obj")
    if os.path.exists(mesh_path):
        os.remove(mesh_path)
    run = subprocess.run(
        [tool, "max(max(abs(x),abs(y)),abs(z))-1", "--box", "-1.5,-1.5,-1.5,1.5,1.5,1.5", "--cells", "16",
         "-o", mesh_path], capture_output=True, text=True, check=False)
    print(run.stdout, end="")
    failures = []
    if run.returncode != 0:
        sys.exit("isopatch_dual_contouring failed (exit %d): %s" % (run.returncode, run.stderr.strip()))
    summary = dict(item.split("=", 1) for item in run.stdout.split())
    positions, triangles = read_obj(mesh_path)
    if int(summary["vertices"]) != len(positions) or int(summary["triangles"]) != len(triangles):
        failures.append("the summary's counts %s/%s are not the file's %d/%d" %
                        (summary["vertices"], summary["triangles"], len(positions), len(triangles)))
    if summary["cells"] != "16":
        failures.append("cells=%s, not 16" % summary["cells"])

    directed = {}
    for t in triangles:
        for i in range(3):
            edge = (t[i], t[(i + 1) % 3])
            directed[edge] = directed.get(edge, 0) + 1
    undirected = {}
    for (a, b), n in directed.items():
        key = (min(a, b), max(a, b))
        undirected[key] = undirected.get(key, 0) + n
    not_two = sum(1 for n in undirected.values() if n != 2)
    if not_two:
        failures.append("%d edges are not in exactly two triangles" % not_two)
    repeated = sum(1 for n in directed.values() if n != 1)
    if repeated:
        failures.append("%d directed edges repeat (inconsistent orientation)" % repeated)
    euler = len(positions) - len(undirected) + len(triangles)
    if euler != 2:
        failures.append("Euler characteristic %d, not 2" % euler)
    volume = signed_volume(positions, triangles)
    if abs(volume - 8.0) > 0.02 * 8.0:
        failures.append("volume %.6f, not within 2%% of 8" % volume)
    worst = 0.0
    for corner in itertools.product((-1.0, 1.0), repeat=3):
        nearest = min(sum((p[i] - corner[i]) ** 2 for i in range(3)) for p in positions) ** 0.5
        worst = max(worst, nearest)
        if nearest > 1e-6:
            failures.append("corner %s: nearest vertex at %.3g" % (corner, nearest))
    print("vertices %d, triangles %d, edges %d, Euler %d, volume %.9f, corner error %.3g" %
          (len(positions), len(triangles), len(undirected), euler, volume, worst))
    if failures:
        sys.exit("dual contouring cube: " + "; ".join(failures))


if __name__ == "__main__":
    main()
