#!/usr/bin/python3
"""isopatch side by side with its Python peers, pygalmesh and scikit-image, at matched vertex counts.

Usage:
    PYTHONPATH=<build>/python /usr/bin/python3 python/bench/compare_peers.py [--quick] [--write-docs]
        [--targets 5000,20000] [--repeats 3] [--threads 0]
(after scripts/run.sh, plain /usr/bin/python3 finds the installed package; pygalmesh and scikit-image are
Debian's python3-pygalmesh and python3-skimage).

Every surface is given three ways: as a formula string (isopatch only), as one numpy function g(x, y, z)
(isopatch.mesh calls it on (N, 3) batches; pygalmesh's Surface_mesher calls the same g point by point
through a pygalmesh.DomainBase; scikit-image needs it sampled on an n^3 grid first) and as that n^3
volume (isopatch.mesh_volume and skimage.measure.marching_cubes; pygalmesh takes no level-set volume,
only labelled images). For each target vertex count every method's size setting (isopatch edge_length,
pygalmesh max_radius_surface_delaunay_ball, scikit-image's grid n) is found by a few secant steps on
log(vertices) so that the mesh lands within 10% of the target; the volume is the n^3 grid that brings
scikit-image to the target. Time is the best of --repeats runs (fewer once a method has used 10 s).

Every mesh is measured by the same code: isopatch.Mesh.from_arrays(vertices, faces, formula).analyze()
against the analytic surface (valence-6 share, smallest angle, normalised RMS error of the discrete mean
curvature at the vertices), and the angle between the normals a method returns and the formula's unit
gradient (pygalmesh returns none: its row measures the mesh's own vertex normals, marked *).

Prints the machine, its load and one Markdown table. --write-docs also rewrites the table in
docs/python.md between the python-peers marker comments. Exits 1 when a method fails or misses its
target by more than 10% (and then writes nothing).
"""

import argparse
import datetime
import math
import os
import pathlib
import platform
import sys
import time

import numpy as np
import pygalmesh
import skimage
from skimage import measure

import isopatch

BOX = ((-1.0, -1.0, -1.0), (1.0, 1.0, 1.0))
TOLERANCE = 0.10  # accepted distance of a vertex count from its target
AIM = 0.03  # the tuning stops once this close
STEPS = 8  # tuning runs at most, per method and target
BUDGET = 10.0  # seconds of timed runs after which a method is not repeated further
DOCS = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"
BEGIN, END = "<!-- python-peers:begin -->", "<!-- python-peers:end -->"

# name: (formula, the same surface as one numpy function of x, y, z that also takes plain floats)
SURFACES = {
    "sphere": ("sqrt(x^2+y^2+z^2) - 0.6", lambda x, y, z: np.sqrt(x * x + y * y + z * z) - 0.6),
    "torus": (
        "sqrt((sqrt(x^2+y^2) - 0.6)^2 + z^2) - 0.25",
        lambda x, y, z: np.sqrt((np.sqrt(x * x + y * y) - 0.6) ** 2 + z * z) - 0.25,
    ),
    # the catalogue's genus-5 tangle cube scaled into the box: a polynomial, not a distance, with saddles
    "tanglecube": (
        "u = 2.6*x; v = 2.6*y; w = 2.6*z; u^4 - 5*u^2 + v^4 - 5*v^2 + w^4 - 5*w^2 + 11.8",
        lambda x, y, z: ((2.6 * x) ** 4 - 5 * (2.6 * x) ** 2 + (2.6 * y) ** 4 - 5 * (2.6 * y) ** 2
                         + (2.6 * z) ** 4 - 5 * (2.6 * z) ** 2 + 11.8),
    ),
}


class Domain(pygalmesh.DomainBase):
    """pygalmesh's view of g: one point per call, inside the sphere around BOX."""

    def __init__(self, g):
        super().__init__()
        self.g = g

    def eval(self, x):
        return float(self.g(x[0], x[1], x[2]))

    def get_bounding_sphere_squared_radius(self):
        return float(sum(c * c for c in BOX[1]))


def batched(g):
    """g as isopatch.mesh takes a Python function: an (N, 3) array in, N values out."""
    return lambda p: g(p[:, 0], p[:, 1], p[:, 2])


def sample(g, n):
    """g on n^3 grid points over BOX, in marching_cubes' axis order, and the spacing."""
    axis = np.linspace(BOX[0][0], BOX[1][0], n)
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    return g(x, y, z), (BOX[1][0] - BOX[0][0]) / (n - 1)


def marching_cubes(volume, h):
    verts, faces, normals, _ = measure.marching_cubes(volume, 0.0, spacing=(h, h, h))
    # marching_cubes' normals descend by default (f < 0 inside): turn them outwards
    return verts + np.array(BOX[0]), faces, -normals


def methods(g, formula, threads, state):
    """The rows of one surface: (input, method, setting, exponent of vertices in it, first guess, run).
    run(setting) returns (vertices, faces, normals or None); `state` carries the volume between rows."""

    def iso_formula(h):
        m = isopatch.mesh(formula, box=BOX, edge_length=h, threads=threads)
        return m.vertices, m.faces, m.normals

    def iso_callable(h):
        m = isopatch.mesh(batched(g), box=BOX, edge_length=h, threads=threads)
        return m.vertices, m.faces, m.normals

    def pygal(r):
        m = pygalmesh.generate_surface_mesh(Domain(g), min_facet_angle=30.0, max_radius_surface_delaunay_ball=r,
                                            max_facet_distance=r / 10, verbose=False)
        return m.points, m.get_cells_type("triangle"), None

    def sampled(n):  # the last grid is kept for the volume rows
        if state.get("n") != n:
            state["volume"], state["n"] = sample(g, n), n
        return state["volume"]

    def sk_callable(n):
        state.pop("n", None)  # sampling is part of this row's time
        return marching_cubes(*sampled(n))

    def sk_volume(_):
        return marching_cubes(*sampled(state["best_n"]))

    def iso_volume(h):
        volume, spacing = sampled(state["best_n"])
        m = isopatch.mesh_volume(volume, spacing=(spacing,) * 3, origin=BOX[0], edge_length=h, threads=threads)
        return m.vertices, m.faces, m.normals

    return [
        ("formula", "isopatch mesh(formula)", "edge_length", -2, 0.08, iso_formula),
        ("callable", "isopatch mesh(callable)", "edge_length", -2, 0.08, iso_callable),
        ("callable", "pygalmesh generate_surface_mesh", "r", -2, 0.06, pygal),
        ("callable", "sample n^3 + skimage marching_cubes", "n", 2, 32, sk_callable),
        ("volume", "skimage marching_cubes", "n", 0, None, sk_volume),  # at the n found just above
        ("volume", "isopatch mesh_volume", "edge_length", -2, 0.08, iso_volume),
    ]


def timed(run, setting):
    start = time.perf_counter()
    vertices, faces, normals = run(setting)
    return time.perf_counter() - start, (np.asarray(vertices, float), np.asarray(faces, np.int64), normals)


def tune(run, guess, exponent, target, integer):
    """Secant steps on log(vertices) against log(setting) until the count is within AIM of the target.
    Returns (setting, best seconds so far, mesh, runs at that setting)."""
    history = []  # (setting, vertices, seconds, mesh)
    setting = guess
    for _ in range(STEPS):
        if integer:
            setting = max(8, int(round(setting)))
        if any(s == setting for s, *_ in history):
            break
        seconds, mesh = timed(run, setting)
        count = len(np.unique(mesh[1]))
        history.append((setting, count, seconds, mesh))
        if abs(count / target - 1) <= AIM:
            break
        slope = exponent
        if len(history) >= 2:
            (s0, c0, *_), (s1, c1, *_) = history[-2:]
            if s0 != s1 and c0 != c1:
                measured = math.log(c1 / c0) / math.log(s1 / s0)
                if measured * exponent > 0:  # same direction: trust it within a factor of two
                    slope = math.copysign(min(max(abs(measured), abs(exponent) / 2), 2 * abs(exponent)), exponent)
        setting = setting * (target / count) ** (1 / slope)
    setting, count, seconds, mesh = min(history, key=lambda r: abs(r[1] / target - 1))
    return setting, seconds, mesh, 1


def compact(vertices, faces, normals):
    """Drops unreferenced vertices (pygalmesh may keep some) and orients the faces outwards."""
    used, faces = np.unique(faces, return_inverse=True)
    faces = faces.reshape(-1, 3)
    vertices = vertices[used]
    normals = None if normals is None else np.asarray(normals, float)[used]
    a, b, c = (vertices[faces[:, i]] for i in range(3))
    if np.einsum("ij,ij->i", a, np.cross(b, c)).sum() < 0:
        faces = faces[:, ::-1]
    return vertices, np.ascontiguousarray(faces), normals


def measure_mesh(vertices, faces, normals, formula):
    """The table's quality columns, the same code for every method."""
    vertices, faces, normals = compact(vertices, faces, normals)
    reference = isopatch.Mesh.from_arrays(vertices, faces, formula, box=BOX)
    report = reference.analyze()
    if normals is None:  # the mesh's own vertex normals
        err = report["accuracy"]["vertex_normal_error_degrees"]
        normal = (err["mean"], err["max"], "*")
    else:
        exact = reference.normals  # the formula's unit gradient at the vertices
        unit = normals / np.linalg.norm(normals, axis=1, keepdims=True)
        err = np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", unit, exact), -1, 1)))
        normal = (err.mean(), err.max(), "")
    return {
        "vertices": len(vertices),
        "valence6": 100 * report["valence"]["share_6"],
        "min_angle": report["shape"]["min_angle_degrees"]["min"],
        "normal": normal,
        "h_nrms": report["accuracy"]["mean_curvature"]["nrms"],
    }


def rate(per_second):
    if per_second >= 1e6:
        return f"{per_second / 1e6:.2f}M"
    if per_second >= 1e3:
        return f"{per_second / 1e3:.0f}k" if per_second >= 1e4 else f"{per_second / 1e3:.1f}k"
    return f"{per_second:.0f}"


def milliseconds(seconds):
    ms = seconds * 1000
    return f"{ms:.2f}" if ms < 10 else f"{ms:.1f}" if ms < 100 else f"{ms:.0f}"


def row(label, method, setting_name, setting, seconds, q, target):
    value = f"{setting}" if isinstance(setting, int) else f"{setting:.4g}"
    flag = "" if abs(q["vertices"] / target - 1) <= TOLERANCE else " (missed)"
    mean, worst, mark = q["normal"]
    return (f"| {label} | {method} | {setting_name} {value} | {q['vertices']}{flag} | {milliseconds(seconds)} | "
            f"{rate(q['vertices'] / seconds)} | {q['valence6']:.1f} | {q['min_angle']:.1f} | "
            f"{mean:.2g} / {worst:.2g}{mark} | {q['h_nrms']:.2g} |")


HEADER = ("| input | method | setting | vertices | ms | vertices/s | valence 6 % | min angle | "
          "normal error mean / max deg | H nRMS |\n|---|---|---|---|---|---|---|---|---|---|")


def run_surface(name, target, args, memory, failures):
    """The rows of one surface at one target count; `memory` holds every method's last (setting, count)."""
    formula, g = SURFACES[name]
    state = {}
    lines = []
    for kind, method, setting_name, exponent, guess, run in methods(g, formula, args.threads, state):
        label = f"{name} {kind}" if kind != "volume" else f"{name} volume {state.get('best_n', '?')}^3"
        try:
            if exponent == 0:  # the volume scikit-image was tuned on: its count is already matched
                run(None)  # samples that grid again if needed, outside the time
                setting, best, mesh, runs = state["best_n"], *timed(run, None), 1
            else:
                key = (name, method)
                if key in memory:  # start from the last target's setting
                    previous, count = memory[key]
                    guess = previous * (target / count) ** (1 / exponent)
                setting, best, mesh, runs = tune(run, guess, exponent, target, setting_name == "n")
                memory[key] = (setting, len(np.unique(mesh[1])))
                if setting_name == "n":
                    state["best_n"] = setting
            spent = best
            while runs < args.repeats and spent < BUDGET:
                seconds, _ = timed(run, setting)
                best, spent, runs = min(best, seconds), spent + seconds, runs + 1
            q = measure_mesh(*mesh, formula)
            if abs(q["vertices"] / target - 1) > TOLERANCE:
                failures.append(f"{label}, {method}: {q['vertices']} vertices for a target of {target}")
            lines.append(row(label, method, setting_name, setting, best, q, target))
        except Exception as error:  # noqa: BLE001 - report every method, then fail
            failures.append(f"{label}, {method}: {type(error).__name__}: {error}")
            lines.append(f"| {label} | {method} | | failed: {type(error).__name__} | | | | | | |")
        print(lines[-1], flush=True)
    return lines


def machine():
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as cpuinfo:
            model = next(line.split(":", 1)[1].strip() for line in cpuinfo if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{model}, {os.cpu_count()} cores"


def load():
    return ", ".join(f"{v:.2f}" for v in os.getloadavg())


def write_docs(text):
    docs = DOCS.read_text()
    begin, end = docs.find(BEGIN), docs.find(END)
    if begin < 0 or end < begin:
        raise SystemExit(f"{DOCS}: no {BEGIN} ... {END} span to rewrite")
    DOCS.write_text(docs[: begin + len(BEGIN)] + "\n" + text + "\n" + docs[end:])
    print(f"rewrote the table in {DOCS}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--quick", action="store_true", help="one small target (1500 vertices), 2 repeats")
    parser.add_argument("--targets", default="5000,20000", help="comma-separated vertex counts")
    parser.add_argument("--repeats", type=int, default=3, help="timed runs per method (best is kept)")
    parser.add_argument("--threads", type=int, default=0, help="isopatch threads (0: every core)")
    parser.add_argument("--write-docs", action="store_true", help="rewrite the table in docs/python.md")
    args = parser.parse_args()
    targets = [1500] if args.quick else [int(t) for t in args.targets.split(",")]
    if args.quick:
        args.repeats = min(args.repeats, 2)

    start, load_before = time.perf_counter(), load()
    print(f"{machine()}; load average {load_before}; isopatch {isopatch.__version__} (threads={args.threads}), "
          f"pygalmesh {pygalmesh.__version__}, scikit-image {skimage.__version__}, numpy {np.__version__}")
    print(HEADER, flush=True)
    memory, failures, lines = {}, [], []
    for name in SURFACES:
        for target in targets:
            lines += run_surface(name, target, args, memory, failures)
    elapsed = time.perf_counter() - start
    summary = (f"Generated by `python/bench/compare_peers.py --write-docs` on {datetime.date.today()}: "
               f"{machine()}, load average {load_before} at the start and {load()} at the end; "
               f"isopatch {isopatch.__version__} (threads={args.threads}, "
               f"{'every core' if args.threads == 0 else 'as set'}), pygalmesh {pygalmesh.__version__}, "
               f"scikit-image {skimage.__version__}, numpy {np.__version__}; targets "
               f"{' and '.join(map(str, targets))} vertices; {elapsed:.0f} s in all.")
    print(summary)
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures), file=sys.stderr)
        return 1
    if args.write_docs:
        write_docs(summary + "\n\n" + HEADER + "\n" + "\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
