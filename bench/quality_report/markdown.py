"""docs/quality.md from the measured runs: header, targets overview, one table per surface."""

from metrics import dig, metrics
import max_error
import targets as target_checks

COLUMNS = [
    ("size", "l"), ("system", "l"), ("knob", "l"), ("vertices", "r"), ("ms", "r"), ("× proj", "r"),
    ("% val 6", "r"), ("min ∠", "r"), ("p1 / p5 ∠", "r"), ("% < 10°", "r"), ("% < 20°", "r"),
    ("H nRMS", "r"), ("max vert dist", "r"), ("max centroid dist", "r"), ("normal err °", "r"),
    ("topology", "l"),
]


def _f(x, spec):
    return "–" if x is None else format(x, spec)


def _pct(x, spec=".1f"):
    return "–" if x is None else format(100 * x, spec)


def _topology(m):
    if m["watertight"] is None:
        return "–"
    letters = "".join(c if m[k] else "-" for c, k in (("W", "watertight"), ("M", "manifold"), ("O", "oriented"),
                                                       ("I", "intersection_free")))
    return f"{letters} g {_f(m['genus'], 'd')} · {_f(m['components'], 'd')} comp"


def _row(label, run, reference_ms):
    if run is None:
        return [label, "?", "", "not run"] + ["–"] * (len(COLUMNS) - 4)
    if not run.ok:
        return [label, run.system, run.knob, f"failed: {run.error}"] + ["–"] * (len(COLUMNS) - 4)
    ratio = "–" if not (run.ms and reference_ms) else (f"{run.ms / reference_ms:.3g}")
    ms = _f(run.ms, ".1f") + (f" (min of {len(run.timings)})" if len(run.timings) > 1 else "")
    if not run.analysis:
        return [label, run.system, run.knob, str(run.vertices), ms, ratio,
                f"analysis failed: {run.analysis_error}"] + ["–"] * (len(COLUMNS) - 7)
    m = metrics(run.analysis)
    return [label, run.system, run.knob, str(run.vertices), ms, ratio, _pct(m["valence6"]),
            _f(m["min_angle"], ".1f"), f"{_f(m['p1_angle'], '.1f')} / {_f(m['p5_angle'], '.1f')}",
            _pct(m["below10"], ".2f"), _pct(m["below20"], ".2f"), _f(m["h_nrms"], ".3g"),
            _f(m["vertex_distance"], ".1e"), _f(m["centroid_distance"], ".1e"), _f(m["normal_error"], ".2f"),
            _topology(m)]


def _table(header, aligns, rows):
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join("---:" if a == "r" else "---" for a in aligns) + "|"]
    lines += ["| " + " | ".join(str(c).replace("|", "\\|") for c in row) + " |" for row in rows]
    return "\n".join(lines)


def surface_section(spec, surface_args, groups, checks):
    out = [f"### {spec.name}", ""]
    kind = {"closed": f"closed, genus {spec.genus}", "open": "open", "singular": "singular"}[spec.kind]
    out.append(f"`{' '.join(surface_args)}` — {kind}" + (f"; {spec.note}" if spec.note else ""))
    if not spec.targeted:
        out.append("")
        out.append("*Reported for information: the quality targets (docs/algorithms.md 7.4) do not apply to this surface.*")
    out.append("")
    rows = []
    for label, by_system in groups:
        proj = by_system.get("projection")
        reference_ms = proj.ms if proj and proj.ok else None
        for system in ("projection", "mc", "cgal"):
            if system in by_system:
                rows.append(_row(label, by_system[system], reference_ms))
    out.append(_table([c for c, _ in COLUMNS], [a for _, a in COLUMNS], rows))
    if checks:
        out += ["", _table(["target (projection)", "status", "measured"], ["l", "l", "l"], checks)]
    out.append("")
    return "\n".join(out)


def overview(results):
    """One line per targeted surface, one column per target."""
    names = None
    rows = []
    for spec, _, _, checks in results:
        if not checks:
            continue
        names = names or [name for name, _, _ in checks]
        rows.append([spec.name] + [status for _, status, _ in checks])
    if not rows:
        return "No targeted surface was measured."
    short = ["topology", "val 6 >= 90%", "min ∠ >= 20°", "none < 10°", "vert dist <= 1e-9",
             "H nRMS <= CGAL/5", "centroid <= CGAL", ">= 100× CGAL"]
    header = ["surface"] + (short if len(short) == len(names) else names)
    return _table(header, ["l"] * len(header), rows)


def adapted_section(adapted):
    """The `--max-error` meshes: one row per surface and error bound, with the targets checked."""
    header = ["surface", "size", "EPS", "vertices", "ms", "% val 6", "min ∠", "% < 10°", "H nRMS",
              "H / CGAL", "ideal / CGAL", "max centroid dist", "/ EPS", "topology", "targets"]
    aligns = ["l", "l", "r", "r", "r", "r", "r", "r", "r", "r", "r", "r", "r", "l", "l"]
    rows, met, total = [], 0, 0
    for spec, runs_by_size, cgal_runs in adapted:
        for label, run in runs_by_size:
            status, why = max_error.check(spec, run, cgal_runs)
            total += 1
            met += status == "met"
            verdict = status + (f" ({why})" if why else "")
            if not run.ok or not run.analysis:
                rows.append([spec.name, label, run.knob] + ["–"] * 11 + [verdict])
                continue
            m = metrics(run.analysis)
            centroid = dig(run.analysis, "accuracy", "centroid_distance", "max")
            ms = _f(run.ms, ".1f") + (f" (min of {len(run.timings)})" if len(run.timings) > 1 else "")
            rows.append([spec.name, label, f"{run.value:.3g}", str(run.vertices), ms, _pct(m["valence6"]),
                         _f(m["min_angle"], ".1f"), _pct(m["below10"], ".2f"), _f(m["h_nrms"], ".3g"),
                         _f(max_error.h_ratio(run, cgal_runs), ".2f"), _f(max_error.ideal_ratio(run, cgal_runs), ".2f"),
                         _f(centroid, ".2e"), _f(None if centroid is None else centroid / run.value, ".2f"),
                         _topology(m), verdict])
    intro = (f"`isopatch mesh SURFACE --max-error EPS` on every closed surface, EPS chosen for about "
             f"{' and '.join(str(t) for _, t in max_error.SIZES)} vertices. Targets: topology and genus, "
             "valence 6 >= 90%, smallest angle >= 20°, vertices on f = 0, and the largest centroid distance "
             "|f|/|grad f| (absolute, the chordal error) below EPS, and H nRMS at most a fifth of CGAL's at "
             "the same vertex count (`H / CGAL`: CGAL's H nRMS interpolated in log-log between its two runs of "
             "the surface that bracket the count, the nearest run's outside them; not checked without CGAL). "
             "`ideal / CGAL`: the same for ideal equilateral rings of the same vertex count with edges shrinking "
             "like the size field, c / sqrt(kappa_max) (`isopatch_ideal_lattice --sizes graded`, see "
             "[quality-method.md](quality-method.md)): what a perfect lattice of this size law would give. "
             f"{met} of {total} meshes meet them all.")
    return "\n".join(["## Curvature-adapted meshes (`--max-error`)", "", intro, "", _table(header, aligns, rows), ""])


def document(header_lines, results, adapted, cgal_note):
    met = sum(1 for _, _, _, c in results for _, s, _ in c if s == target_checks.MET)
    total = sum(1 for _, _, _, c in results for _, s, _ in c if s != target_checks.NA)
    parts = ["# Quality report", "", "*Generated by `scripts/quality_report.sh`; do not edit by hand. "
             "Method and column definitions: [quality-method.md](quality-method.md).*", ""]
    parts += header_lines
    parts += ["", "## Quality targets (docs/algorithms.md 7.4; projection meshes, every size)", "",
              f"{met} of {total} checks met. {cgal_note}", "", overview(results), "",
              *([adapted_section(adapted)] if adapted else []),
              "## Results per surface", "",
              "Columns: `knob` the size parameter (projection edge length h, marching-cubes grid, CGAL radius "
              "bound R); `ms` meshing wall time (minimum of the repetitions shown); `× proj` time over the "
              "projection's time in the same size group; `% val 6` share of interior vertices of valence 6; "
              "angles are each triangle's smallest angle in degrees (min, 1st / 5th percentile); `% < 10°` "
              "and `% < 20°` share of triangles; `H nRMS` normalized RMS error of the cotangent mean "
              "curvature; distances are maxima of |f|/|grad f| at vertices and at triangle centroids divided "
              "by the box diagonal; `normal err` mean angle between triangle normal and grad f; topology "
              "`W M O I` = watertight, manifold, consistently oriented, free of self-intersections (a `-` marks a "
              "failure), genus, "
              "components.", ""]
    for spec, surface_args, groups, checks in results:
        parts.append(surface_section(spec, surface_args, groups, checks))
    return "\n".join(parts).rstrip() + "\n"
