"""Measuring one surface at one size: every system at the vertex count isopatch's default sets,
fitted first, then timed again in interleaved rounds (each round runs every system once; the
minimum is kept), then analysed with `isopatch analyze`."""

import glob
import math
import os
import sys
from dataclasses import dataclass, field

import matching
import runs
import systems

REMESH_TOLERANCE = 0.05
SYSTEMS = ["default 2t", "default 1t", "default 4t", "preview", "fine", "pipeline", systems.FINE_PIPELINE, "raw",
           "cgal", "fe", "fe + remesh"]
ANALYSED = ["default 2t", "preview", "fine", "pipeline", systems.FINE_PIPELINE, "raw", "cgal", "fe", "fe + remesh"]


@dataclass
class Tools:
    isopatch: str
    cgal: str  # "" when not built
    vtk: str
    remesh: str
    work: str
    repeats: int
    keep_meshes: bool = False


@dataclass
class Group:
    """One surface at one size: the runs by system name (SYSTEMS)."""
    label: str
    target: int
    runs: dict = field(default_factory=dict)
    load: float | None = None  # 1-minute load average when the group started


def log(message: str) -> None:
    print(f"[performance] {message}", file=sys.stderr, flush=True)


def _missing(system: str, why: str) -> systems.Timed:
    return systems.Timed(system, "–", 0.0, error=why)


def _fit_remesh(tools: Tools, fe: systems.Timed, count: int, tag: str) -> systems.Timed:
    """FE + remeshing with the target edge whose vertex count is closest to `count`."""
    tried, edge = [], None
    for attempt in range(matching.MAX_ATTEMPTS):
        run = systems.remesh(tools.remesh, fe, edge, count, os.path.join(tools.work, f"{tag}-{attempt}.ply"))
        runs.log_attempt(run)
        tried.append(run)
        if not run.ok or abs(run.vertices / count - 1) <= REMESH_TOLERANCE:
            break
        edge = run.value * math.sqrt(run.vertices / count)
    ok = [r for r in tried if r.ok]
    return min(ok, key=lambda r: abs(math.log(r.vertices / count))) if ok else tried[-1]


def _isopatch_maker(tools, surface, quality, threads):
    return lambda h, out: systems.isopatch(tools.isopatch, surface, h, quality, threads, out)


def _fit(tools, surface, target, side, tag, known, quality):
    """isopatch `--quality quality` on 2 threads fitted to `target` vertices; `known` holds the earlier
    fits of the surface by quality (a quality's first fit starts from the default's runs)."""
    pool = known.setdefault(quality, [])
    seed = pool if pool else [r for r in known.get("default", []) if r.ok]
    run = matching.match_projection(tools.isopatch, surface, target, side, tools.work, tag, seed,
                                    make=_isopatch_maker(tools, surface, quality, 2))
    if seed is not pool:
        pool.extend(r for r in seed if r.ok and r.quality == quality)
    return run


def fit_flying_edges(tools, surface, count, known, tag) -> systems.Timed:
    """VTK Flying Edges on 2 threads with the grid whose vertex count is closest to `count`. V ~ c g^2:
    `known["fe_c"]` (from an earlier Flying Edges run of the surface, updated here) gives the first grid."""
    if not tools.vtk:
        return _missing("vtk fe", "isopatch_vtk_peer not built (VTK not found)")
    make = lambda g, out: systems.flying_edges(tools.vtk, surface, g, 2, out)  # noqa: E731
    start = max(2, round(math.sqrt(count / known["fe_c"]))) if "fe_c" in known else 64
    fe = matching.match_mc("", surface, count, tools.work, tag, make=make, grid=start)
    if fe.ok:
        known["fe_c"] = fe.vertices / fe.value**2
    return fe


def _fine_one_level(tools, surface, fine, default, tag) -> systems.Timed:
    """fine at one level (`--quality fine --refine 1`) at the fine run's edge length (the default's when
    fine failed), run once (slow, and only its quality is compared: no fitting, no repetition)."""
    base = fine if fine.ok else default
    if not base.ok:
        return _missing(systems.FINE_PIPELINE, "no fine or default run to take the edge length from")
    run = systems.isopatch(tools.isopatch, surface, base.value, systems.FINE_PIPELINE, 2,
                           os.path.join(tools.work, f"{tag}-x.ply"))
    runs.log_attempt(run)
    return run


def _fit_all(tools, name, surface, side, label, target, known) -> dict:
    """Every system fitted to the count of isopatch's default (2 threads); the chosen runs by name."""
    tag = lambda system: f"{name}-{label}-{system.replace(' ', '')}"  # noqa: E731
    r = {}
    d2 = _fit(tools, surface, target, side, tag("default2t"), known, "default")
    r["default 2t"] = d2
    count = d2.vertices if d2.ok else target
    if d2.ok:
        out = lambda t: os.path.join(tools.work, f"{tag(f'default{t}t')}-x.ply")  # noqa: E731
        r["default 1t"] = systems.isopatch(tools.isopatch, surface, d2.value, "default", 1, out(1))
        r["default 4t"] = systems.isopatch(tools.isopatch, surface, d2.value, "default", 4, out(4))
        # The paper's method alone at the default's edge length: what the clean-up starts from (its
        # count is lower, the collapses and splits change it; vertices per second compare all the same).
        r["raw"] = systems.isopatch(tools.isopatch, surface, d2.value, systems.RAW, 2, out("raw"))
        runs.analyze(tools.isopatch, d2, surface)
    for quality in ("preview", "fine", systems.PIPELINE):
        r[quality] = _fit(tools, surface, count, side, tag(quality), known, quality)
    r[systems.FINE_PIPELINE] = _fine_one_level(tools, surface, r["fine"], d2, tag(systems.FINE_PIPELINE))
    r["fe"] = fit_flying_edges(tools, surface, count, known, tag("fe"))
    if r["fe"].ok:
        r["fe + remesh"] = _fit_remesh(tools, r["fe"], count, tag("remesh")) if tools.remesh else _missing(
            "fe + remesh", "isopatch_cgal_remesh not built (CGAL not found)")
    else:
        r["fe + remesh"] = _missing("fe + remesh", r["fe"].error if not tools.vtk else "Flying Edges failed")
    if tools.cgal:
        radius = matching.cgal_first_radius(known.setdefault("cgal", []), d2 if d2.analysis else None, count, side)
        c = matching.match_cgal(tools.cgal, surface, count, radius, tools.work, tag("cgal"))
        if c.ok:
            known["cgal"].append(c)
        r["cgal"] = systems.Timed(**vars(c))  # its CPU time comes from the repetitions
    else:
        r["cgal"] = _missing("cgal", "isopatch_cgal_peer not built (CGAL not found)")
    return r


def _again(tools, surface, name, run, chosen):
    """A function that repeats `run` (same knob, same output file), or None when it is not repeated (4
    threads: only its bytes count; fine at one level: slow, only its quality counts)."""
    if not run.ok or name in ("default 4t", systems.FINE_PIPELINE):
        return None
    if name.startswith("default") or name in ("preview", "fine", "pipeline", "raw"):
        return lambda: systems.isopatch(tools.isopatch, surface, run.value, run.quality, run.threads, run.mesh)
    if name == "fe":
        return lambda: systems.flying_edges(tools.vtk, surface, int(run.value), run.threads, run.mesh)
    if name == "fe + remesh":
        return lambda: systems.remesh(tools.remesh, chosen["fe"], run.value, 0, run.mesh)
    if name == "cgal":
        return lambda: systems.cgal(tools.cgal, surface, run.value, run.mesh)
    return None


def measure(tools: Tools, name: str, surface: list[str], side: float, label: str, target: int, known: dict) -> Group:
    """`name` surface (its command-line arguments `surface`) at about `target` vertices; `known` keeps
    the fits of the surface's earlier sizes."""
    group = Group(label, target, load=os.getloadavg()[0])
    chosen = _fit_all(tools, name, surface, side, label, target, known)
    for _ in range(tools.repeats - 1):
        for system in SYSTEMS:
            again = _again(tools, surface, system, chosen.get(system, _missing(system, "")), chosen)
            if again is not None:
                systems.add_timing(chosen[system], again())
    for system in ANALYSED:
        run = chosen.get(system)
        if run is not None and run.ok and run.analysis is None:
            runs.analyze(tools.isopatch, run, surface)
    for system, run in chosen.items():
        log(f"{name} {label} {system:12s} " + (f"{run.vertices} vertices, {run.ms:.1f} ms" if run.ok
                                                else f"FAILED {run.error}"))
    if not tools.keep_meshes:
        keep = set()
    else:
        keep = {run.mesh for run in chosen.values() if run.ok}
    for path in glob.glob(os.path.join(tools.work, f"{name}-{label}-*")):
        if path not in keep:
            os.remove(path)
    group.runs = chosen
    return group
