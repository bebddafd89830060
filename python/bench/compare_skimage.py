#!/usr/bin/python3
"""isopatch against scikit-image's marching_cubes on the same sampled volumes and Python functions.

Usage: PYTHONPATH=<build>/python /usr/bin/python3 python/bench/compare_skimage.py [--quick]
(after scripts/run.sh, plain /usr/bin/python3 finds the installed package). Prints one Markdown table:
time, vertices, valence-6 share, smallest angle, normal error of the returned normals and mean-curvature
error (discrete, at the vertices) against the analytic surface. Every mesh is measured by the same
code (isopatch.Mesh.from_arrays(...).analyze()). pygalmesh is not packaged for Debian 12 (and PyPI is
out of reach here), so it is not compared.
"""

import argparse
import time

import numpy as np
from skimage import measure

import isopatch

SURFACES = {
    # name: (numpy function, formula of the same surface, exact unit normal)
    "sphere": (
        lambda p: np.linalg.norm(p, axis=1) - 0.6,
        "sqrt(x^2+y^2+z^2) - 0.6",
        lambda p: p / np.linalg.norm(p, axis=1, keepdims=True),
    ),
    "torus": (
        lambda p: np.hypot(np.hypot(p[:, 0], p[:, 1]) - 0.6, p[:, 2]) - 0.25,
        "sqrt((sqrt(x^2+y^2) - 0.6)^2 + z^2) - 0.25",
        None,
    ),
}


def torus_normal(p):
    rho = np.hypot(p[:, 0], p[:, 1])
    d = p - np.stack([p[:, 0] / rho * 0.6, p[:, 1] / rho * 0.6, np.zeros(len(p))], axis=1)
    return d / np.linalg.norm(d, axis=1, keepdims=True)


def angles(a, b):
    a = a / np.linalg.norm(a, axis=1, keepdims=True)
    return np.degrees(np.arccos(np.clip(np.sum(a * b, axis=1), -1, 1)))


def sample(f, n):
    axis = np.linspace(-1.0, 1.0, n)
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    return f(np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)).reshape(n, n, n), 2.0 / (n - 1)


def row(label, method, seconds, vertices, faces, normals, formula, exact_normal):
    """One table row, and the mesh's median edge length."""
    report = isopatch.Mesh.from_arrays(vertices, faces, formula, box=((-1,) * 3, (1,) * 3)).analyze()
    err = angles(normals, exact_normal(vertices))
    text = (f"| {label} | {method} | {seconds * 1000:.0f} | {len(vertices)} | "
            f"{100 * report['valence']['share_6']:.1f} | {report['shape']['min_angle_degrees']['min']:.1f} | "
            f"{err.mean():.2g} / {err.max():.2g} | {report['accuracy']['mean_curvature']['nrms']:.3f} |")
    return text, report["shape"]["edge_length"]["median"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true", help="32^3 and 64^3 only")
    args = parser.parse_args()
    sizes = [32, 64] if args.quick else [32, 64, 128]
    print("| input | method | ms | vertices | valence 6 % | min angle | normal error mean / max deg | H nRMS |")
    print("|---|---|---|---|---|---|---|---|")
    for name, (f, formula, normal) in SURFACES.items():
        normal = normal or torus_normal
        for n in sizes:
            volume, h = sample(f, n)
            label = f"{name} volume {n}^3"
            start = time.perf_counter()
            verts, faces, normals, _ = measure.marching_cubes(volume, 0.0, spacing=(h, h, h))
            seconds = time.perf_counter() - start
            text, edge = row(label, "skimage marching_cubes", seconds, verts - 1.0, faces, -normals, formula, normal)
            print(text)
            start = time.perf_counter()
            m = isopatch.mesh_volume(volume, spacing=(h, h, h), origin=(-1, -1, -1))
            seconds = time.perf_counter() - start
            print(row(label, "isopatch mesh_volume", seconds, m.vertices, m.faces, m.normals, formula, normal)[0])
            start = time.perf_counter()
            m = isopatch.mesh_volume(volume, spacing=(h, h, h), origin=(-1, -1, -1), edge_length=edge)
            seconds = time.perf_counter() - start
            print(row(label, "isopatch, skimage's median edge", seconds, m.vertices, m.faces, m.normals, formula,
                      normal)[0])
        # The function itself: isopatch calls it in batches; skimage needs it sampled first (128^3).
        box = ((-1.0,) * 3, (1.0,) * 3)
        start = time.perf_counter()
        volume, h = sample(f, 129)
        verts, faces, normals, _ = measure.marching_cubes(volume, 0.0, spacing=(h, h, h))
        seconds = time.perf_counter() - start
        print(row(f"{name} function", "sample 129^3 + skimage", seconds, verts - 1.0, faces, -normals, formula,
                  normal)[0])
        start = time.perf_counter()
        m = isopatch.mesh(f, box=box)
        seconds = time.perf_counter() - start
        print(row(f"{name} function", "isopatch mesh(callable)", seconds, m.vertices, m.faces, m.normals, formula,
                  normal)[0])
        start = time.perf_counter()
        m = isopatch.mesh(formula, box=box)
        seconds = time.perf_counter() - start
        print(row(f"{name} function", "isopatch mesh(formula)", seconds, m.vertices, m.faces, m.normals, formula,
                  normal)[0])


if __name__ == "__main__":
    main()
