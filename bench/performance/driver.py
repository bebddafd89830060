"""Performance report driver (called by scripts/performance_report.sh): isopatch (default on 1, 2 and
4 threads, preview, fine), CGAL's Surface_mesher, VTK Flying Edges and Flying Edges + CGAL's
isotropic remeshing side by side on every public closed surface at matched vertex counts (about 20k
and 200k), one isopatch mesh of about 1M vertices with its peak memory, and docs/performance.md.
Every number comes from this run.
"""

import argparse
import glob
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "quality_report"))

import building  # noqa: E402
import machine  # noqa: E402
import main as quality_main  # noqa: E402  (catalogue and box helpers of the quality report)
import matching  # noqa: E402
import measure  # noqa: E402
import report  # noqa: E402
import systems  # noqa: E402
from surfaces import PUBLIC_SURFACES  # noqa: E402

SIZES = [("20k", 20_000), ("200k", 200_000)]
QUICK_SURFACES = ["sphere", "torus", "tanglecube"]
LARGE_SURFACE, LARGE_VERTICES = "sphere", 1_000_000
REPEATS = 3


REFERENCE_RUNS = 3  # small runs timed before and again after the large one


def large_run(tools: measure.Tools, surface: list[str], known: dict, vertices: int,
              small: systems.Timed | None) -> systems.Timed:
    """isopatch default on 2 threads at about `vertices` vertices (edge length from the surface's
    earlier fits, no fitting of its own) under /usr/bin/time -v. With `small` (the surface's default run
    at the first size), that run's configuration is timed again REFERENCE_RUNS times just before and just
    after the large run (minimum kept, in run.reference): the time per vertex is compared side by side,
    not with a run made long before under another load."""
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
    for path in (out, out + ".stats.json", small_out, small_out + ".stats.json"):
        if os.path.exists(path) and not tools.keep_meshes:
            os.remove(path)
    return run


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
    args = parser.parse_args()
    if args.isopatch:
        args.isopatch = os.path.join(args.cwd, args.isopatch)
    os.chdir(args.repo)
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
    closed = [s for s in PUBLIC_SURFACES if s.kind == "closed"]
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
        small = next((g.runs.get("default 2t") for sp, _, gs in results if sp.name == LARGE_SURFACE
                      for g in gs if g.label == sizes[0][0]), None)
        large = large_run(tools, surface, known, args.large, small)
        for path in glob.glob(os.path.join(tools.work, f"{spec.name}-sizing-*")):
            os.remove(path)
        loads.append(os.getloadavg()[0])

    seconds = time.monotonic() - start
    header = machine.header(args.repo, args.command, seconds, bool(args.cgal), args.quick)
    header += report.tool_lines(args, loads)
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(report.document(header, results, large, sizes))
    with open(os.path.join(args.work, "results.json"), "w", encoding="utf-8") as f:
        json.dump({"surfaces": [{"surface": spec.name, "args": surface,
                                 "groups": [{"size": g.label, "target": g.target, "load": g.load,
                                             "runs": {k: vars(r) for k, r in g.runs.items()}} for g in groups]}
                                for spec, surface, groups in results],
                   "large": None if large is None else vars(large), "seconds": seconds}, f, indent=1, default=str)
    measure.log(f"wrote {args.out} in {seconds / 60:.1f} min")
    return 0


if __name__ == "__main__":
    sys.exit(main())
