"""The figures of the performance report from the measured groups: speeds, ratios, geometric means
and the targets of issue 20, each target with its status and the measured value."""

import math

import targets as quality_targets
from metrics import metrics

MET, NOT_MET, NA = quality_targets.MET, quality_targets.NOT_MET, quality_targets.NA

TARGET_CGAL = 20.0  # default's vertices/s over CGAL's
TARGET_REMESH = 10.0  # default's vertices/s over FE + remeshing's
TARGET_PREVIEW_FE = 0.25  # preview's vertices/s over Flying Edges'
TARGET_SPEEDUP = 1.7  # 2 threads over 1
TARGET_LARGE_TIME = 1.5  # time per vertex at 1M over the 20k case's
TARGET_BYTES = 300.0  # peak memory per output vertex at 1M
QUALITY_TARGET_NAMES = ("watertight", "valence 6", "smallest angle", "no angle", "vertex distance", "H nRMS")


def speed(run) -> float | None:
    """Vertices per second of wall time, None for a failed or untimed run."""
    return run.vertices / (run.ms / 1e3) if run is not None and run.ok and run.ms and run.vertices else None


def ratio(a, b) -> float | None:
    return a / b if a is not None and b else None


def gmean(values) -> float | None:
    v = [x for x in values if x is not None and x > 0]
    return math.exp(sum(math.log(x) for x in v) / len(v)) if v else None


def quality(run) -> dict | None:
    return metrics(run.analysis) if run is not None and run.ok and run.analysis else None


def per_vertex(count, run) -> float | None:
    return count / run.vertices if count is not None and run is not None and run.ok and run.vertices else None


def speedup(group) -> float | None:
    return ratio(speed(group.runs.get("default 2t")), speed(group.runs.get("default 1t")))


def identical(group) -> bool | None:
    """The default mesh's bytes are the same for 1, 2 and 4 threads (None when a run is missing)."""
    hashes = [getattr(group.runs.get(f"default {t}t"), "sha256", None) for t in (1, 2, 4)]
    return None if None in hashes else len(set(hashes)) == 1


RATIOS = [  # (name, numerator system, denominator system, target text)
    ("isopatch default ÷ CGAL Surface_mesher", "default 2t", "cgal", f">= {TARGET_CGAL:g}"),
    ("isopatch default ÷ FE + isotropic remeshing", "default 2t", "fe + remesh", f">= {TARGET_REMESH:g}"),
    ("isopatch preview ÷ VTK Flying Edges", "preview", "fe", f">= {TARGET_PREVIEW_FE:g}"),
    ("isopatch default, 2 threads ÷ 1 thread", "default 2t", "default 1t", f">= {TARGET_SPEEDUP:g}"),
    ("isopatch default ÷ VTK Flying Edges", "default 2t", "fe", "–"),
    ("isopatch fine ÷ CGAL Surface_mesher", "fine", "cgal", "–"),
    ("isopatch preview ÷ CGAL Surface_mesher", "preview", "cgal", "–"),
    ("the paper's method alone (isopatch --remesh 0) ÷ CGAL Surface_mesher", "raw", "cgal", "–"),
    ("the paper's method alone ÷ FE + isotropic remeshing", "raw", "fe + remesh", "–"),
    ("the paper's method alone ÷ VTK Flying Edges", "raw", "fe", "–"),
]

BUDGETS = [  # (the system a speed target is about, its denominator, the target ratio)
    ("default 2t", "cgal", TARGET_CGAL),
    ("default 2t", "fe + remesh", TARGET_REMESH),
    ("preview", "fe", TARGET_PREVIEW_FE),
]


def allowed_ms(group, system, peer, target) -> float | None:
    """The wall time (ms) a speed target allows `system` for its own vertex count: that count at
    `target` times the peer's vertices per second."""
    run, v = group.runs.get(system), speed(group.runs.get(peer))
    return 1e3 * run.vertices / (target * v) if run is not None and run.ok and run.vertices and v else None


def raw_ms_at(group, system) -> float | None:
    """The time the paper's method alone (no clean-up) takes for as many vertices as `system` made, at
    its own vertices per second: the part of the budget the clean-up cannot have."""
    run, v = group.runs.get(system), speed(group.runs.get("raw"))
    return 1e3 * run.vertices / v if run is not None and run.ok and run.vertices and v else None


def group_ratio(group, a, b) -> float | None:
    return ratio(speed(group.runs.get(a)), speed(group.runs.get(b)))


def ratio_means(results, label) -> dict:
    """{(a, b): geometric mean over the surfaces of speed(a) / speed(b)} at size `label`."""
    out = {}
    for _, a, b, _ in RATIOS:
        out[(a, b)] = gmean(group_ratio(g, a, b) for _, _, groups in results for g in groups if g.label == label)
    return out


def large_figures(results, large, first_label):
    """(time per vertex of the large run ÷ that of the same surface's first size, bytes per vertex). The
    small run is the one timed around the large run when there is one (the same load), else the
    surface's run at the first size."""
    if large is None or not large.ok:
        return None, None
    small = getattr(large, "reference", None)
    if small is None or not small.ok:
        for spec, _, groups in results:
            if spec.name == "sphere":
                small = next((g.runs.get("default 2t") for g in groups if g.label == first_label), None)
    per_v = lambda r: r.ms / r.vertices if r is not None and r.ok and r.ms else None  # noqa: E731
    bytes_per_v = 1024.0 * large.max_rss_kb / large.vertices if large.max_rss_kb else None
    return ratio(per_v(large), per_v(small)), bytes_per_v


def _status(ok) -> str:
    return NA if ok is None else (MET if ok else NOT_MET)


def _every(results, label, value, ok, describe):
    """Status and detail of a per-surface condition that must hold on every surface of size `label`."""
    values = [(spec.name, value(g)) for spec, _, groups in results for g in groups if g.label == label]
    if not values:
        return NA, "not measured"
    bad = [(n, v) for n, v in values if v is None or not ok(v)]
    if not bad:
        numbers = sorted(v for _, v in values if isinstance(v, (int, float)) and not isinstance(v, bool))
        spread = f" ({describe(numbers[0])} to {describe(numbers[-1])})" if numbers else ""
        return MET, f"all {len(values)} surfaces{spread}"
    return NOT_MET, f"{len(values) - len(bad)} of {len(values)} surfaces; " + "; ".join(
        f"{n} {describe(v)}" for n, v in bad)


def default_quality(spec, group) -> tuple[str, str]:
    """The quality targets docs/quality.md checks (quality_report/targets.py), on the default mesh."""
    checks = quality_targets.check(spec, [(group.label, {"projection": group.runs.get("default 2t"),
                                                         "cgal": group.runs.get("cgal")})])
    kept = [(name, status) for name, status, _ in checks if name.startswith(QUALITY_TARGET_NAMES)]
    failed = [name.split(" (")[0] for name, status in kept if status == NOT_MET]
    return (NOT_MET if failed else MET), ("; ".join(failed) if failed else "all met")


def _fmt(x, spec=".3g", suffix="") -> str:
    return "–" if x is None else format(x, spec) + suffix


def target_rows(results, large, labels) -> list[list[str]]:
    """[target, size, status, measured] for every target of issue 20."""
    rows = []
    for label in labels:
        means = ratio_means(results, label)
        statuses = [(spec.name, default_quality(spec, g)) for spec, _, gs in results for g in gs if g.label == label]
        bad = [f"{n}: {why}" for n, (s, why) in statuses if s != MET]
        rows.append(["default: the quality targets of docs/quality.md", label,
                     NOT_MET if bad else (MET if statuses else NA),
                     f"{len(statuses) - len(bad)} of {len(statuses)} surfaces meet all" + (
                         " (not met: " + "; ".join(bad) + ")" if bad else "")])
        for name, a, b, target in RATIOS[:4]:
            threshold = float(target.split()[-1])
            v = means[(a, b)]
            rows.append([f"{name} (vertices/s, geometric mean) {target}", label,
                         _status(None if v is None else v >= threshold), _fmt(v, ".3g", "×")])
        preview = lambda g: quality(g.runs.get("preview"))  # noqa: E731
        rows.append(["preview: valence 6 >= 90%", label, *_every(
            results, label, lambda g: (preview(g) or {}).get("valence6"), lambda v: v >= 0.90,
            lambda v: _fmt(None if v is None else 100 * v, ".1f", "%"))])
        rows.append(["preview: smallest angle >= 20°", label, *_every(
            results, label, lambda g: (preview(g) or {}).get("min_angle"), lambda v: v >= 20.0,
            lambda v: _fmt(v, ".1f", "°"))])
        rows.append(["preview: vertices on f = 0 (max |f|/|grad f| <= 1e-9 of the diagonal)", label, *_every(
            results, label, lambda g: (preview(g) or {}).get("vertex_distance"),
            lambda v: v <= quality_targets.MAX_VERTEX_DISTANCE, lambda v: _fmt(v, ".1e"))])
        rows.append(["preview: H nRMS <= CGAL's", label, *_every(
            results, label, lambda g: ratio((preview(g) or {}).get("h_nrms"),
                                            (quality(g.runs.get("cgal")) or {}).get("h_nrms")),
            lambda v: v <= 1.0, lambda v: _fmt(v, ".2f", "× CGAL's"))])
        rows.append(["output bytes equal for 1, 2 and 4 threads (default)", label, *_every(
            results, label, identical, lambda v: v, lambda v: "differ" if v is False else "not measured")])
        rows.append(["evaluations of f and grad f per vertex in the statistics (default)", label, *_every(
            results, label, lambda g: getattr(g.runs.get("default 2t"), "gradient_evaluations", None) is not None
            and getattr(g.runs.get("default 2t"), "value_evaluations", None) is not None,
            lambda v: v, lambda v: "missing")])
    time_ratio, bytes_per_v = large_figures(results, large, labels[0])
    count = f" ({large.vertices} vertices)" if large is not None and large.ok else ""
    rows.append([f"1M-vertex mesh{count}: time per vertex <= {TARGET_LARGE_TIME:g}× the {labels[0]} case's (sphere)",
                 "large", _status(None if time_ratio is None else time_ratio <= TARGET_LARGE_TIME),
                 _fmt(time_ratio, ".2f", "×")])
    rows.append([f"1M-vertex mesh{count}: peak memory <= {TARGET_BYTES:g} bytes per output vertex", "large",
                 _status(None if bytes_per_v is None else bytes_per_v <= TARGET_BYTES), _fmt(bytes_per_v, ".0f", " B")])
    return rows
