"""Random models and settings, from a seed (issue 56): formulas built from primitives (spheres,
ellipsoids, boxes, cylinders, tori, gyroid slabs) joined by union, intersection, difference and
offsets, in boxes that hold them or cut them, with regions, frames and settings drawn at random. Each
case goes through isopatch.mesh in a process of its own (`python3 random_models.py CASE` prints the
outcome as JSON), so that a crash or a hang is seen as such. An outcome is a mesh that passes the checks
below ("mesh"), a refusal: an isopatch error with a one-line message ("refused"), a mesh that fails a
check but whose statistics carry warnings ("warned"), or one that fails silently ("invalid"). Used by test_random_models.py (50
cases in the test command) and scripts/random_models.py (2,000 cases, docs/robustness.md)."""
import json
import math
import random
import sys


def _centre(rng, spread=0.6):
    return [round(rng.uniform(-spread, spread), 3) for _ in range(3)]


def _at(c):
    return f"(x-({c[0]}))", f"(y-({c[1]}))", f"(z-({c[2]}))"


def primitive(rng):
    """A solid f < 0 of size about 1 near the origin, as a formula."""
    kind = rng.choice(["sphere", "ellipsoid", "box", "cylinder", "torus", "gyroid_slab"])
    x, y, z = _at(_centre(rng))
    if kind == "sphere":
        r = round(rng.uniform(0.4, 1.0), 3)
        return f"{x}^2+{y}^2+{z}^2-{round(r * r, 6)}"
    if kind == "ellipsoid":
        a, b, c = (round(rng.uniform(0.4, 1.1), 3) for _ in range(3))
        return f"({x}/{a})^2+({y}/{b})^2+({z}/{c})^2-1"
    if kind == "box":
        a, b, c = (round(rng.uniform(0.3, 0.9), 3) for _ in range(3))
        return f"max(max(abs({x})-{a},abs({y})-{b}),abs({z})-{c})"
    if kind == "cylinder":
        r, h = round(rng.uniform(0.2, 0.6), 3), round(rng.uniform(0.4, 1.0), 3)
        return f"max({x}^2+{y}^2-{round(r * r, 6)},abs({z})-{h})"
    if kind == "torus":
        big, small = round(rng.uniform(0.5, 0.9), 3), round(rng.uniform(0.15, 0.35), 3)
        return f"(sqrt({x}^2+{y}^2)-{big})^2+{z}^2-{round(small * small, 6)}"
    s = round(rng.uniform(3.0, 6.0), 3)  # a gyroid solid inside a ball
    gyroid = f"sin({s}*x)*cos({s}*y)+sin({s}*y)*cos({s}*z)+sin({s}*z)*cos({s}*x)"
    return f"max({gyroid},x^2+y^2+z^2-1)"


def model(rng, depth):
    if depth == 0 or rng.random() < 0.3:
        return primitive(rng)
    a, b = model(rng, depth - 1), model(rng, depth - 1)
    op = rng.choice(["union", "intersection", "difference", "offset"])
    if op == "union":
        return f"min({a},{b})"
    if op == "intersection":
        return f"max({a},{b})"
    if op == "difference":
        return f"max({a},-({b}))"
    return f"({a})-({round(rng.uniform(-0.05, 0.1), 3)})"


def case(seed):
    """The case of a seed: a formula, a box and the keyword arguments of isopatch.mesh."""
    rng = random.Random(seed)
    formula = model(rng, rng.choice([0, 1, 1, 2, 2, 3]))
    half = rng.choice([1.6, 1.6, 1.6, 1.0, 0.7])  # 1.6 holds the solids; smaller boxes cut them
    box = [[round(-half + rng.uniform(-0.1, 0.1), 3) for _ in range(3)],
           [round(half + rng.uniform(-0.1, 0.1), 3) for _ in range(3)]]
    settings = {
        "edge_length": round(2 * half / rng.choice([16, 24, 32, 40]), 4),
        "quality": rng.choice(["preview", "default", "default"]),
        "creases": rng.choice(["auto", "auto", "auto", "off"]),
        "threads": rng.choice([1, 2]),
        "max_vertices": 300000,
        "time_limit": 50.0,
    }
    if rng.random() < 0.15:
        n = [rng.uniform(-1, 1) for _ in range(3)]
        length = math.sqrt(sum(v * v for v in n)) or 1.0
        settings["region"] = [[round(v / length, 4) for v in n] + [round(rng.uniform(-0.4, 0.2), 3)]]
    elif rng.random() < 0.15:
        settings["frame"] = [round(rng.uniform(-180, 180), 1), round(rng.uniform(-80, 80), 1),
                             round(rng.uniform(-180, 180), 1)]
    return {"seed": seed, "formula": formula, "box": box, "settings": settings}


def boundary_off_the_cut(vertices, faces, box, settings):
    """Boundary vertices farther than 1e-9 of the diagonal from every box face and region plane."""
    import numpy as np

    edges = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    unique, counts = np.unique(edges, axis=0, return_counts=True)
    on_boundary = np.unique(unique[counts == 1])
    if on_boundary.size == 0:
        return 0
    p = vertices[on_boundary]
    lo, hi = np.array(box[0]), np.array(box[1])
    tolerance = 1e-9 * float(np.linalg.norm(hi - lo))
    near = np.zeros(len(p), dtype=bool)
    for axis in range(3):
        near |= np.abs(p[:, axis] - lo[axis]) <= tolerance
        near |= np.abs(p[:, axis] - hi[axis]) <= tolerance
    for a, b, c, d in settings.get("region", []):
        near |= np.abs(p @ np.array([a, b, c]) + d) <= tolerance * max(1.0, math.sqrt(a * a + b * b + c * c))
    return int((~near).sum())


def run(the_case):
    """Meshes a case and checks the mesh; the outcome as a dict."""
    import isopatch

    s = dict(the_case["settings"])
    region = s.pop("region", None)
    frame = s.pop("frame", None)
    try:
        mesh = isopatch.mesh(the_case["formula"], box=the_case["box"], region=region, frame=frame, **s)
    except isopatch.Error as error:
        message = str(error)
        return {"outcome": "refused", "kind": type(error).__name__, "message": message,
                "one_line": "\n" not in message.strip() and bool(message.strip())}
    if len(mesh.faces) == 0:
        return {"outcome": "invalid", "why": "an empty mesh without an error"}
    report = mesh.analyze(surface=False)
    topology, crossings = report["topology"], report["self_intersections"]
    problems = []
    for name in ("non_manifold_edges", "non_manifold_vertices", "degenerate_triangles"):
        if topology[name]:
            problems.append(f"{name} {topology[name]}")
    if not topology["consistently_oriented"]:
        problems.append("inconsistently oriented")
    if crossings["pairs"]:
        problems.append(f"{crossings['pairs']} self-intersecting pairs")
    if topology["watertight"] and not topology["outward_oriented"]:
        problems.append("closed but not outward")
    loose = boundary_off_the_cut(mesh.vertices, mesh.faces, the_case["box"], the_case["settings"])
    if loose:
        problems.append(f"{loose} boundary vertices off the box and the region")
    warnings = sorted(k for k, v in mesh.stats.get("warnings", {}).items() if v)
    # A mesh with problems is "warned" when its statistics carry warnings (the tool prints them; Python
    # has them in stats['warnings']), "invalid" when nothing said so: a silent wrong mesh.
    verdict = ("warned" if warnings else "invalid") if problems else "mesh"
    outcome = {"outcome": verdict, "vertices": int(len(mesh.vertices)),
               "closed": bool(topology["watertight"]), "smallest_angle": report["shape"]["min_angle_degrees"]["min"],
               "warnings": warnings}
    if problems:
        outcome["why"] = "; ".join(problems)
    return outcome


if __name__ == "__main__":
    print(json.dumps(run(json.loads(sys.argv[1]))))
