"""The targets of docs/algorithms.md 7.4 checked on the projection meshes of one surface, over every size."""

from metrics import metrics

MET, NOT_MET, NA = "met", "**not met**", "n/a"

# The thresholds of docs/algorithms.md 7.4, shared with the --max-error checks (max_error.py).
MIN_VALENCE6 = 0.90
MIN_ANGLE = 20.0
MAX_VERTEX_DISTANCE = 1e-9  # relative to the box diagonal
MAX_H_RATIO = 0.2  # H nRMS over CGAL's at a comparable vertex count


def _fmt(x, spec=".3g"):
    return "–" if x is None else format(x, spec)


def _per_size(groups, system):
    """[(size label, run, metrics)] of `system` over the size groups."""
    out = []
    for label, runs_by_system in groups:
        run = runs_by_system.get(system)
        out.append((label, run, metrics(run.analysis) if run and run.analysis else None))
    return out


def _failed(rows):
    bad = [label for label, run, m in rows if m is None]
    return f"no analysed projection mesh at {', '.join(bad)}" if bad else None


def _threshold(rows, key, ok, describe):
    failed = _failed(rows)
    if failed:
        return NOT_MET, failed
    values = [(label, m[key]) for label, _, m in rows]
    if any(v is None for _, v in values):
        return NOT_MET, f"{key} missing from the analysis"
    bad = [(label, v) for label, v in values if not ok(v)]
    detail = ", ".join(f"{label} {describe(v)}" for label, v in values)
    return (NOT_MET if bad else MET), detail


def _topology(rows, genus):
    failed = _failed(rows)
    if failed:
        return NOT_MET, failed
    problems = []
    for label, _, m in rows:
        flags = [name for name in ("watertight", "manifold", "oriented", "outward", "intersection_free")
                 if m[name] is not True]
        if m["components"] != 1:
            flags.append(f"{m['components']} components")
        if genus is not None and m["genus"] != genus:
            flags.append(f"genus {m['genus']} (want {genus})")
        if flags:
            problems.append(f"{label}: not " + ", ".join(flags))
    return (NOT_MET, "; ".join(problems)) if problems else (MET, f"genus {genus}, one component, at every size")


def _versus_cgal(groups, key, ok, describe):
    pairs = []
    for label, by_system in groups:
        p, c = by_system.get("projection"), by_system.get("cgal")
        if not (c and c.analysis):
            continue
        mp = metrics(p.analysis) if p and p.analysis else None
        mc = metrics(c.analysis)
        pairs.append((label, None if mp is None else key(p, mp, c, mc)))
    if not pairs:
        return NA, "no CGAL mesh in this run"
    if any(v is None for _, v in pairs):
        return NOT_MET, "a projection mesh or a value is missing where CGAL has one"
    detail = ", ".join(f"{label} {describe(v)}" for label, v in pairs)
    return (MET if all(ok(v) for _, v in pairs) else NOT_MET), detail


def h_versus_cgal(p, mp, c, mc):
    """(our H nRMS / CGAL's, the ideal lattice's / CGAL's or None), or None without both H values. The
    ideal lattice (run.ideal, bench/ideal_lattice) is the H nRMS of perfect equilateral rings at the
    projection mesh's vertex count: how far below CGAL a mesh of that size can get without grading."""
    if mp["h_nrms"] is None or not mc["h_nrms"]:
        return None
    ideal = (p.ideal or {}).get("nrms_mean")
    return mp["h_nrms"] / mc["h_nrms"], None if ideal is None else ideal / mc["h_nrms"]


def describe_h_ratio(v) -> str:
    return f"{v[0]:.3f}× CGAL's" + ("" if v[1] is None else f" (ideal lattice {v[1]:.2f}×)")


def check(spec, groups) -> list[tuple[str, str, str]]:
    """[(target, status, detail)] for the projection rows of one surface."""
    rows = _per_size(groups, "projection")
    out = [("watertight, manifold, outward, no self-intersections, genus, 1 component", *_topology(rows, spec.genus))]
    out.append(("valence 6 >= 90% of interior vertices",
                *_threshold(rows, "valence6", lambda v: v >= MIN_VALENCE6, lambda v: f"{100 * v:.1f}%")))
    out.append(("smallest angle >= 20°",
                *_threshold(rows, "min_angle", lambda v: v >= MIN_ANGLE, lambda v: f"{v:.1f}°")))
    out.append(("no angle < 10°",
                *_threshold(rows, "below10", lambda v: v == 0, lambda v: f"{100 * v:.2f}% under 10°")))
    out.append(("vertex distance <= 1e-9 diagonal",
                *_threshold(rows, "vertex_distance", lambda v: v <= MAX_VERTEX_DISTANCE, lambda v: f"{v:.1e}")))

    def ratio(key):
        return lambda p, mp, c, mc: None if mp[key] is None or not mc[key] else mp[key] / mc[key]

    out.append(("H nRMS <= CGAL's / 5", *_versus_cgal(groups, h_versus_cgal, lambda v: v[0] <= MAX_H_RATIO,
                                                      describe_h_ratio)))
    out.append(("centroid distance <= CGAL's (chordal error; not one of the quality targets)",
                *_versus_cgal(groups, ratio("centroid_distance"), lambda v: v <= 1.0, lambda v: f"{v:.2f}× CGAL's")))
    speed = (lambda p, mp, c, mc: None if not (p.ms and c.ms) else
             (c.ms / c.vertices) / (p.ms / p.vertices))
    out.append(("faster than CGAL >= 100× (per output vertex)",
                *_versus_cgal(groups, speed, lambda v: v >= 100, lambda v: f"{v:.0f}×")))
    return out
