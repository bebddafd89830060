"""Performance report driver (called by scripts/performance_report.sh): isopatch (default on 1, 2 and
4 threads, preview, fine, the default and fine at one level, the paper's method alone), CGAL's
Surface_mesher, VTK Flying Edges and Flying Edges + CGAL's isotropic remeshing side by side on every
public closed surface at matched vertex counts (about 20k and 200k), one isopatch mesh of about 1M
vertices with its peak memory and Flying Edges at its count, and docs/performance.md checked against
issue 34's targets. Every number comes from this run (or, with --from-results, from an earlier run's
results.json, without measuring).
"""

import argparse
import glob
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "quality_report"))

import building  # noqa: E402
import figures  # noqa: E402
import machine  # noqa: E402
import main as quality_main  # noqa: E402  (catalogue and box helpers of the quality report)
import matching  # noqa: E402
import measure  # noqa: E402
import report  # noqa: E402
import results_file  # noqa: E402
import systems  # noqa: E402
from surfaces import PUBLIC_SURFACES  # noqa: E402

SIZES = [("20k", 20_000), ("200k", 200_000)]
QUICK_SURFACES = ["sphere", "torus", "tanglecube"]
LARGE_SURFACE, LARGE_VERTICES = figures.LARGE_SURFACE, 1_000_000
REPEATS = 3


REFERENCE_RUNS = 3  # small runs timed before and again after the large one


def large_run(tools: measure.Tools, surface: list[str], known: dict, vertices: int,
              small: systems.Timed | None) -> systems.Timed:
    """isopatch default on 2 threads at about `vertices` vertices (edge length from the surface's
    earlier fits, no fitting of its own) under /usr/bin/time -v. With `small` (the surface's default run
    at the reference size, figures.reference_label), that run's configuration is timed again
    REFERENCE_RUNS times just before and just after the large run (minimum kept, in run.reference): the
    time per vertex is compared side by side, not with a run made long before under another load. Flying
    Edges is then fitted to the large run's count (run.fe)."""
    pool = [r for r in known.get("default", []) if r.ok]
    if not pool:
        return measure._missing("isopatch default", "no earlier default run of the surface to size it from")
    h = matching._next_size(pool, vertices)
    out = os.path.join(tools.work, f"{LARGE_SURFACE}-large.ply")
    small_out = os.path.join(tools.work, f"{LARGE_SURFACE}-large-reference.ply")
    reference = None

    def time_reference():
        nonlocal reference
        if small is None or not small.ok:
            return
        for _ in range(REFERENCE_RUNS):
            again = systems.isopatch(tools.isopatch, surface, small.value, "default", 2, small_out)
            if reference is None:
                reference = again
            else:
                systems.add_timing(reference, again)

    time_reference()
    measure.log(f"{LARGE_SURFACE}: about {vertices} vertices with h {h:.4g} (peak memory measured)")
    run = systems.isopatch_peak_memory(tools.isopatch, surface, h, 2, out)
    time_reference()
    run.reference = reference
    if run.ok:
        run.fe = large_flying_edges(tools, surface, known, run.vertices)
    for path in (out, out + ".stats.json", small_out, small_out + ".stats.json"):
        if os.path.exists(path) and not tools.keep_meshes:
            os.remove(path)
    return run


def large_flying_edges(tools: measure.Tools, surface: list[str], known: dict, count: int) -> systems.Timed:
    """VTK Flying Edges fitted to `count` vertices as at the other sizes (measure.fit_flying_edges), then
    timed tools.repeats times in all (minimum kept); its mesh removed unless kept."""
    measure.log(f"{LARGE_SURFACE}: Flying Edges at about {count} vertices")
    tag = f"{LARGE_SURFACE}-large-fe"
    fe = measure.fit_flying_edges(tools, surface, count, known, tag)
    for _ in range(tools.repeats - 1):
        if fe.ok:
            systems.add_timing(fe, systems.flying_edges(tools.vtk, surface, int(fe.value), fe.threads, fe.mesh))
    keep = {fe.mesh} if tools.keep_meshes and fe.ok else set()
    for path in glob.glob(os.path.join(tools.work, f"{tag}-*")):
        if path not in keep:
            os.remove(path)
    return fe


def _reference_run(results, sizes) -> systems.Timed | None:
    """The large surface's default run (2 threads) at the reference size (figures.reference_label)."""
    label = figures.reference_label([label for label, _ in sizes])
    return next((g.runs.get("default 2t") for sp, _, gs in results if sp.name == LARGE_SURFACE
                 for g in gs if g.label == label), None)


def from_results(args, closed) -> int:
    """Rebuilds the report from a results.json (args.from_results) without measuring."""
    try:
        saved = results_file.load(args.from_results, closed)
    except (OSError, ValueError, KeyError) as e:
        measure.log(f"cannot read {args.from_results}: {e}")
        return 2
    header, note = saved["header"], ""
    if header is None:  # an older file: the header rebuilt from what it holds
        note = "; the file keeps no header: the date, load, commit and runtime above are the rebuild's or guessed"
        runs_of = [r for _, _, gs in saved["results"] for g in gs for r in g.runs.values()]
        args.tool = args.isopatch or os.path.join(args.build, "bin", "isopatch")
        args.vtk = any(r.ok and r.system == "vtk fe" for r in runs_of)
        args.remesh = any(r.ok and r.system == "fe + remesh" for r in runs_of)
        args.repeats = max((len(r.timings) for r in runs_of if r.ok), default=1)
        header = machine.header(args.repo, args.command, saved["seconds"],
                                any(r.ok and r.system == "cgal" for r in runs_of), len(saved["sizes"]) < 2)
        header += report.tool_lines(args, saved["loads"])
    shown = os.path.relpath(args.from_results)
    header = header + [f"- rebuilt from `{args.from_results if shown.startswith('..') else shown}` without "
                       f"measuring{note}"]
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(report.document(header, saved["results"], saved["large"], saved["sizes"]))
    measure.log(f"wrote {args.out} from {args.from_results}")
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("isopatch", nargs="?", default="", help="the isopatch binary (default: BUILD/bin/isopatch)")
    parser.add_argument("--build", default=os.environ.get("ISOPATCH_BUILD", "build-bench"), help="build folder")
    parser.add_argument("--no-build", action="store_true", help="use the build folder as it is")
    parser.add_argument("--out", default="docs/performance.md", help="the Markdown report to write")
    parser.add_argument("--work", default="out/performance", help="folder for the meshes and results.json")
    parser.add_argument("--repo", default=".", help="repository root (for the commit in the header)")
    parser.add_argument("--cwd", default=".", help="the folder a relative ISOPATCH_BIN is relative to")
    parser.add_argument("--quick", action="store_true", help=f"{', '.join(QUICK_SURFACES)} at 20k only")
    parser.add_argument("--surfaces", default="", help="comma-separated subset of the public closed surfaces")
    parser.add_argument("--sizes", default="", help="comma-separated subset of the sizes (" +
                        ",".join(label for label, _ in SIZES) + ")")
    parser.add_argument("--repeats", type=int, default=REPEATS, help="timed runs per system (minimum kept)")
    parser.add_argument("--large", type=int, default=LARGE_VERTICES, help="vertices of the large run (0: none)")
    parser.add_argument("--keep-meshes", action="store_true", help="keep the chosen meshes in the work folder")
    parser.add_argument("--command", default="scripts/performance_report.sh", help="the command shown in the header")
    parser.add_argument("--from-results", default="", metavar="FILE",
                        help="rebuild the report from an earlier run's results.json, without measuring")
    args = parser.parse_args()
    if args.isopatch:
        args.isopatch = os.path.join(args.cwd, args.isopatch)
    if args.from_results:
        args.from_results = os.path.join(args.cwd, args.from_results)
    os.chdir(args.repo)
    closed = [s for s in PUBLIC_SURFACES if s.kind == "closed"]
    if args.from_results:
        return from_results(args, closed)
    if not args.no_build:
        try:
            building.build(args.repo, args.build, not args.isopatch, measure.log)
        except subprocess.CalledProcessError as e:
            measure.log(f"build failed: {e}")
            return 2
    args.tool = args.isopatch or os.path.join(args.build, "bin", "isopatch")
    if not os.access(args.tool, os.X_OK):
        measure.log(f"{args.tool} not found: build first or drop --no-build")
        return 2
    args.cgal, args.remesh, args.vtk = (building.peer(args.build, name, measure.log) for name in building.PEERS)

    start = time.monotonic()
    os.makedirs(args.work, exist_ok=True)
    tools = measure.Tools(args.tool, args.cgal, args.vtk, args.remesh, args.work, max(1, args.repeats),
                          args.keep_meshes)
    names = quality_main.catalogue(args.tool)
    wanted = [s for s in args.surfaces.split(",") if s] or (QUICK_SURFACES if args.quick else [])
    unknown = set(wanted) - {s.name for s in closed}
    if unknown:
        measure.log(f"not a public closed surface: {', '.join(sorted(unknown))}")
        return 2
    sizes = SIZES[:1] if args.quick else SIZES
    if args.sizes:
        sizes = [(label, n) for label, n in SIZES if label in args.sizes.split(",")]
        if len(sizes) != len(args.sizes.split(",")):
            measure.log(f"unknown size in {args.sizes} (want {', '.join(label for label, _ in SIZES)})")
            return 2
    loads = [os.getloadavg()[0]]
    results, known_by_surface = [], {}
    for spec in closed:
        if wanted and spec.name not in wanted:
            continue
        surface = spec.cli_args(set(names))
        side = quality_main.longest_side(names.get(spec.name, spec.box))
        known = known_by_surface.setdefault(spec.name, {})
        groups = []
        for label, target in sizes:
            measure.log(f"--- {spec.name} at about {target} vertices")
            groups.append(measure.measure(tools, spec.name, surface, side, label, target, known))
            loads.append(os.getloadavg()[0])
        results.append((spec, surface, groups))

    large = None
    if args.large > 0:
        spec = next(s for s in closed if s.name == LARGE_SURFACE)
        surface = spec.cli_args(set(names))
        known = known_by_surface.setdefault(spec.name, {})
        if not known.get("default"):
            side = quality_main.longest_side(names.get(spec.name, spec.box))
            measure._fit(tools, surface, sizes[0][1], side, f"{spec.name}-sizing", known, "default")
        large = large_run(tools, surface, known, args.large, _reference_run(results, sizes))
        for path in glob.glob(os.path.join(tools.work, f"{spec.name}-sizing-*")):
            os.remove(path)
        loads.append(os.getloadavg()[0])

    seconds = time.monotonic() - start
    header = machine.header(args.repo, args.command, seconds, bool(args.cgal), args.quick)
    header += report.tool_lines(args, loads)
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(report.document(header, results, large, sizes))
    results_file.save(os.path.join(args.work, "results.json"), results, large, sizes, seconds, header, loads)
    measure.log(f"wrote {args.out} in {seconds / 60:.1f} min")
    return 0


if __name__ == "__main__":
    sys.exit(main())
