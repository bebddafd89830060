#!/usr/bin/python3
"""An OpenVDB level set meshed from its .vdb file and from its samples made dense (.npy path).

Usage: PYTHONPATH=<build>/python /usr/bin/python3 python/bench/vdb_vs_npy.py
Makes a sphere (radius 1, createLevelSetSphere) and a torus (radii 1 and 0.4, createLevelSetFromPolygons
of a 960 x 480 quad mesh) with Debian's python3-openvdb at voxel sizes 0.05 and 0.025, writes each to a
.vdb file, and meshes it with isopatch.mesh_volume twice: from the file (the sparse quasi-interpolant,
docs/python.md "OpenVDB level sets") and from copyToArray of its active bounds with the same spacing and
origin (the dense interpolant). Prints one Markdown table: time, vertices, valence-6 share, smallest
angle, mean-curvature nRMS and the largest vertex distance against the analytic surface, all measured by
Mesh.from_arrays(...).analyze().
"""

import os
import tempfile
import time

import numpy as np
import pyopenvdb as vdb

import isopatch

SPHERE = "sqrt(x^2+y^2+z^2) - 1"
TORUS = "sqrt((sqrt(x^2+y^2) - 1)^2 + z^2) - 0.4"


def torus_grid(voxel, nu=960, nv=480):
    u = np.linspace(0, 2 * np.pi, nu, endpoint=False)
    v = np.linspace(0, 2 * np.pi, nv, endpoint=False)
    U, V = np.meshgrid(u, v, indexing="ij")
    points = np.stack([(1 + 0.4 * np.cos(V)) * np.cos(U), (1 + 0.4 * np.cos(V)) * np.sin(U), 0.4 * np.sin(V)], -1)
    index = np.arange(nu * nv).reshape(nu, nv)
    nxt_u, nxt_v = np.roll(index, -1, 0), np.roll(index, -1, 1)
    quads = np.stack([index, nxt_u, np.roll(nxt_u, -1, 1), nxt_v], -1).reshape(-1, 4)
    g = vdb.FloatGrid.createLevelSetFromPolygons(points.reshape(-1, 3).astype(np.float32),
                                                 quads=quads.astype(np.uint32),
                                                 transform=vdb.createLinearTransform(voxelSize=voxel), halfWidth=3.0)
    g.name = "torus"
    return g


def row(name, voxel, active, path, seconds, m, formula):
    r = isopatch.Mesh.from_arrays(m.vertices, m.faces, formula, box=((-2,) * 3, (2,) * 3)).analyze()
    return (f"| {name} | {voxel} | {active} | {path} | {len(m.vertices)} | {seconds:.2f} | "
            f"{100 * r['valence']['share_6']:.2f} | {r['shape']['min_angle_degrees']['min']:.1f} | "
            f"{r['accuracy']['mean_curvature']['nrms']:.4f} | {r['accuracy']['vertex_distance']['max']:.1e} |")


def main():
    print(f"machine: {os.cpu_count()} cores, load average {', '.join(f'{v:.2f}' for v in os.getloadavg())}")
    print("| grid | voxel | active voxels | path | vertices | s | valence 6 % | min angle | H nRMS | max distance |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for voxel in (0.05, 0.025):
            sphere = vdb.createLevelSetSphere(radius=1.0, center=(0, 0, 0), voxelSize=voxel, halfWidth=3.0)
            sphere.name = "sphere"
            for g, formula in ((sphere, SPHERE), (torus_grid(voxel), TORUS)):
                path = os.path.join(folder, f"{g.name}.vdb")
                vdb.write(path, grids=[g])
                start = time.perf_counter()
                m = isopatch.mesh_volume(path)
                print(row(g.name, voxel, g.activeVoxelCount(), ".vdb", time.perf_counter() - start, m, formula))
                lo, hi = g.evalActiveVoxelBoundingBox()
                array = np.zeros(tuple(h - l + 1 for l, h in zip(lo, hi)), np.float32)
                g.copyToArray(array, ijk=lo)
                start = time.perf_counter()
                m = isopatch.mesh_volume(array.astype(np.float64), spacing=(voxel,) * 3,
                                         origin=tuple(voxel * c for c in lo))
                print(row(g.name, voxel, f"({array.size} dense)", ".npy", time.perf_counter() - start, m, formula))


if __name__ == "__main__":
    main()
