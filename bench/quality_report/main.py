"""Quality report driver (called by scripts/quality_report.sh): meshes every public surface at three
sizes with projection, marching cubes and CGAL's Surface_mesher at matched vertex counts, analyses
every mesh with `isopatch analyze` and writes docs/quality.md. Every number comes from this run.
"""

import argparse
import glob
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/
import hard_shapes  # noqa: E402
import machine
import markdown
import matching
import max_error
import runs
import targets
from surfaces import PUBLIC_SURFACES

SIZES = [("small", 2000), ("medium", 10000), ("large", 40000)]
TIMING_REPEATS = 3  # projection and marching cubes are timed this often (minimum kept); CGAL once


def log(message: str) -> None:
    print(f"[quality] {message}", file=sys.stderr, flush=True)


def catalogue(tool: str) -> dict[str, str]:
    """name -> box of `isopatch surfaces`."""
    code, stdout, err = runs.run_command([tool, "surfaces"], 60)
    if code != 0:
        log(f"isopatch surfaces failed ({err.strip()}); every surface is taken as given")
        return {}
    return {m.group(1): m.group(2) for m in re.finditer(r"^(\w+)\s.*\bbox\s+(\S+)", stdout, re.MULTILINE)}


def box_corners(box: str | None) -> list[float]:
    """lo and hi of "x0,y0,z0,x1,y1,z1" as six numbers; the cube [-1, 1]^3 when it does not parse."""
    try:
        v = [float(x) for x in box.split(",")]
        if len(v) == 6:
            return v
    except (AttributeError, ValueError):
        pass
    return [-1.0, -1.0, -1.0, 1.0, 1.0, 1.0]


def longest_side(box: str | None) -> float:
    v = box_corners(box)
    return max(v[3] - v[0], v[4] - v[1], v[5] - v[2])


def diagonal(box: str | None) -> float:
    v = box_corners(box)
    return math.dist(v[:3], v[3:])


def describe(run: runs.Run) -> str:
    return f"{run.system:10s} {run.knob:18s} " + (f"{run.vertices} vertices, {run.ms:.1f} ms" if run.ok else
                                                   f"FAILED {run.error}")


def finish(run: runs.Run, tool: str, surface: list[str], again, tag: str, work: str) -> runs.Run:
    """Times the chosen run again (projection, MC), analyses it and removes the other trial meshes."""
    if run.ok and again is not None:
        for _ in range(TIMING_REPEATS - 1):
            runs.repeat_timing(run, again)
    runs.analyze(tool, run, surface)
    for path in glob.glob(os.path.join(work, f"{tag}-*.ply")):
        if path != run.mesh:
            os.remove(path)
    log("chose " + describe(run) + ("" if run.analysis or not run.ok else f" (analysis failed: {run.analysis_error})"))
    return run


def measure_surface(spec, args, names, work):
    surface = spec.cli_args(set(names))
    side = longest_side(names.get(spec.name, spec.box))
    groups, cgal_runs, projection_runs = [], [], []
    sizes = SIZES[:1] if args.quick else SIZES
    for label, target in sizes:
        tag = f"{spec.name}-{label}"
        p = matching.match_projection(args.tool, surface, target, side, work, f"{tag}-projection",
                                      projection_runs)
        p = finish(p, args.tool, surface, lambda p=p: runs.projection(args.tool, surface, p.value, p.mesh),
                   f"{tag}-projection", work)
        runs.ideal_lattice(args.ideal, p, surface, "uniform")
        count = p.vertices if p.ok else target
        m = matching.match_mc(args.tool, surface, count, work, f"{tag}-mc")
        m = finish(m, args.tool, surface, lambda m=m: runs.marching_cubes(args.tool, surface, int(m.value), m.mesh),
                   f"{tag}-mc", work)
        by_system = {"projection": p, "mc": m}
        if args.peer:
            reference = p if p.ok and p.analysis else (m if m.ok and m.analysis else None)
            radius = matching.cgal_first_radius(cgal_runs, reference, count, side)
            c = matching.match_cgal(args.peer, surface, count, radius, work, f"{tag}-cgal")
            c = finish(c, args.tool, surface, None, f"{tag}-cgal", work)
            cgal_runs.append(c)
        else:
            c = runs.Run("cgal", "–", 0.0, error="CGAL peer not built (CGAL not found)")
        by_system["cgal"] = c
        groups.append((label, by_system))
    checks = targets.check(spec, groups) if spec.targeted else []
    adapted = []
    if spec.targeted and not args.quick:
        def finish_adapted(run, again, tag):
            run = finish(run, args.tool, surface, again, tag, work)
            runs.ideal_lattice(args.ideal, run, surface, "graded")
            return run

        adapted = max_error.measure(args.tool, spec, surface, diagonal(names.get(spec.name, spec.box)), work,
                                    finish_adapted)
    return (spec, surface, groups, checks), adapted, cgal_runs


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--tool", required=True, help="the isopatch command-line tool")
    parser.add_argument("--peer", default="", help="isopatch_cgal_peer (empty: no CGAL rows)")
    parser.add_argument("--ideal", default="", help="isopatch_ideal_lattice (empty: no ideal-lattice yardstick)")
    parser.add_argument("--out", required=True, help="the Markdown report to write")
    parser.add_argument("--work", required=True, help="folder for the meshes and results.json")
    parser.add_argument("--repo", default=".", help="repository root (for the commit in the header)")
    parser.add_argument("--quick", action="store_true", help="one size (about 2k vertices), for smoke tests")
    parser.add_argument("--surfaces", default="", help="comma-separated subset of the public surfaces")
    parser.add_argument("--command", default="scripts/quality_report.sh", help="the command shown in the header")
    args = parser.parse_args()

    start = runs.now()
    os.makedirs(args.work, exist_ok=True)
    names = catalogue(args.tool)
    wanted = [s for s in args.surfaces.split(",") if s]
    unknown = set(wanted) - {s.name for s in PUBLIC_SURFACES}
    if unknown:
        log(f"unknown surface(s): {', '.join(sorted(unknown))}")
        return 2
    results, adapted = [], []
    for spec in PUBLIC_SURFACES:
        if wanted and spec.name not in wanted:
            continue
        log(f"--- {spec.name}")
        measured, adapted_runs, cgal_runs = measure_surface(spec, args, names, args.work)
        results.append(measured)
        if adapted_runs:
            adapted.append((spec, adapted_runs, cgal_runs))

    hard = ""
    if not args.quick and not wanted:
        log("--- shapes that break the floor most easily (bench/hard_shapes.py)")
        hard = hard_shapes.section(hard_shapes.run_all(args.tool, os.path.join(args.work, "hard_shapes")),
                                   "/usr/bin/python3 bench/hard_shapes.py")
    seconds = runs.now() - start
    header = machine.header(args.repo, args.command, seconds, bool(args.peer), args.quick)
    cgal_note = "" if args.peer else "CGAL was not built, so the checks against CGAL are n/a."
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(markdown.document(header, results, adapted, cgal_note))
        if hard:
            f.write("\n" + hard)
    with open(os.path.join(args.work, "results.json"), "w", encoding="utf-8") as f:
        json.dump([{"surface": spec.name, "args": surface,
                    "groups": [{"size": label, "runs": {k: vars(r) for k, r in by.items()}} for label, by in groups],
                    "targets": checks,
                    "max_error": [{"size": label, "run": vars(r)} for s2, rs, _ in adapted if s2 is spec for label, r in rs]}
                   for spec, surface, groups, checks in results], f, indent=1)
    log(f"wrote {args.out} in {seconds / 60:.1f} min")
    return 0


if __name__ == "__main__":
    sys.exit(main())
