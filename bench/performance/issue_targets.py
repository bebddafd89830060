"""The targets of issue 34 (the multiresolution refinement, its "Done when"), each as a row [target, size,
status, measured]: speed ratios as geometric means over the surfaces, conditions that must hold on every
surface, the large mesh. A target at a size that was not measured, or about a system that was not run
(a peer not built, an old results file), is "n/a" and says so; the thresholds are in figures.py."""

import figures as fig
import targets as quality_targets
from figures import MET, NA, NOT_MET, _fmt

SHOWN = {"default 2t": "default", "preview": "preview", "fine": "fine", "pipeline": "one level (--refine 1)",
         "fine pipeline": "fine at one level", "cgal": "CGAL", "fe": "Flying Edges"}


def _status(ok) -> str:
    return NA if ok is None else (MET if ok else NOT_MET)


def _percent(v) -> str:
    return _fmt(None if v is None else 100 * v, ".1f", "%")


def _degrees(v) -> str:
    return _fmt(v, ".1f", "°")


def _times(what):
    return lambda v: _fmt(v, ".2f", f"× {what}")


def _metric(system, key):
    """group -> the metric `key` (metrics.py) of the group's analysed `system` run, or None."""
    return lambda g: (fig.quality(g.runs.get(system)) or {}).get(key)


def _h_over(system, other):
    """group -> H nRMS of `system` over that of `other`, or None."""
    return lambda g: fig.ratio(_metric(system, "h_nrms")(g), _metric(other, "h_nrms")(g))


def _per_vertex(system, key):
    """group -> `key` evaluations (value_evaluations, gradient_evaluations) per output vertex of `system`."""
    return lambda g: fig.per_vertex(getattr(g.runs.get(system), key, None), g.runs.get(system))


def _reported(g) -> bool:
    d = g.runs.get("default 2t")
    return getattr(d, "gradient_evaluations", None) is not None and getattr(d, "value_evaluations", None) is not None


D, P, F = "default 2t", "preview", "fine"
H_CGAL = f"H nRMS <= CGAL's / {1 / fig.DEFAULT_H_CGAL:g}"
# (sizes (None: every measured size), target, systems it needs, value of a group, ok, describe the value)
DEFAULT_CONDITIONS = [
    ((fig.TARGET_SIZE,), f"default: valence 6 >= {100 * fig.DEFAULT_VALENCE6:g}% on every surface", (D,),
     _metric(D, "valence6"), lambda v: v >= fig.DEFAULT_VALENCE6, _percent),
    ((fig.TARGET_SIZE,), f"default: smallest angle >= {fig.DEFAULT_ANGLE:g}° on every surface", (D,),
     _metric(D, "min_angle"), lambda v: v >= fig.DEFAULT_ANGLE, _degrees),
    ((fig.TARGET_SIZE,), f"default: {H_CGAL} on every surface", (D, "cgal"), _h_over(D, "cgal"),
     lambda v: v <= fig.DEFAULT_H_CGAL, _times("CGAL's")),
    ((fig.TARGET_SIZE,), "default: H nRMS <= one level's (--refine 1, fitted to the same vertex count) on every "
     "surface", (D, "pipeline"), _h_over(D, "pipeline"), lambda v: v <= fig.DEFAULT_H_ONE_LEVEL,
     _times("one level's")),
]
PREVIEW_CONDITIONS = [
    ((fig.TARGET_SIZE,), f"preview: valence 6 >= {100 * fig.PREVIEW_VALENCE6:g}% on every surface", (P,),
     _metric(P, "valence6"), lambda v: v >= fig.PREVIEW_VALENCE6, _percent),
    ((fig.TARGET_SIZE,), f"preview: smallest angle >= {fig.PREVIEW_ANGLE:g}° on every surface", (P,),
     _metric(P, "min_angle"), lambda v: v >= fig.PREVIEW_ANGLE, _degrees),
    ((fig.TARGET_SIZE,), "preview: H nRMS <= CGAL's on every surface", (P, "cgal"), _h_over(P, "cgal"),
     lambda v: v <= fig.PREVIEW_H_CGAL, _times("CGAL's")),
]
FINE_CONDITIONS = [
    ((fig.SMALL_SIZE, fig.TARGET_SIZE), f"fine: H nRMS <= fine at one level's (--quality fine --refine 1, same "
     f"edge length) / {1 / fig.FINE_H_ONE_LEVEL:g} on every surface", (F, "fine pipeline"),
     _h_over(F, "fine pipeline"), lambda v: v <= fig.FINE_H_ONE_LEVEL, _times("one level's")),
]
EVERY_SIZE_CONDITIONS = [
    (None, "output bytes equal for 1, 2 and 4 threads (default)", ("default 1t", D, "default 4t"), fig.identical,
     lambda v: v, lambda v: "differ" if v is False else "not measured"),
    (None, "evaluations of f and grad f per output vertex in the statistics (default)", (D,), _reported,
     lambda v: v, lambda v: "missing"),
    (None, f"default: evaluations of grad f per output vertex <= {fig.TARGET_GRADIENTS:g} (the aim) on "
     "every surface", (D,), _per_vertex(D, "gradient_evaluations"), lambda v: v <= fig.TARGET_GRADIENTS,
     lambda v: _fmt(v, ".3g")),
]


def _ran(run) -> bool:
    """The system was run (a peer that is not built, or a system an old results file lacks, was not)."""
    return run is not None and (run.ok or "not built" not in (run.error or ""))


def _every(results, label, labels, needs, value, ok, describe) -> tuple[str, str]:
    """Status and detail of a condition that must hold on every surface measured at size `label`."""
    if label not in labels:
        return NA, f"not measured (no {label} run)"
    groups = [(spec.name, g) for spec, _, gs in results for g in gs if g.label == label]
    ran = [(name, g) for name, g in groups if all(_ran(g.runs.get(s)) for s in needs)]
    if not ran:
        absent = [s for s in needs if not any(_ran(g.runs.get(s)) for _, g in groups)] or needs
        return NA, "not measured (no " + " or ".join(SHOWN.get(s, s) for s in absent) + " run)"
    values = [(name, value(g)) for name, g in ran]
    bad = [f"{name} " + ("no value (a run failed)" if v is None else describe(v))
           for name, v in values if v is None or not ok(v)]
    done = {id(g) for _, g in ran}
    bad += [f"{name} not run" for name, g in groups if id(g) not in done]
    if not bad:
        numbers = sorted(v for _, v in values if isinstance(v, (int, float)) and not isinstance(v, bool))
        spread = "" if not numbers else f" ({describe(numbers[0])})" if numbers[0] == numbers[-1] else (
            f" ({describe(numbers[0])} to {describe(numbers[-1])})")
        return MET, f"all {len(values)} surface{'' if len(values) == 1 else 's'}{spread}"
    return NOT_MET, f"{len(groups) - len(bad)} of {len(groups)} surfaces; " + "; ".join(bad)


def _condition_rows(results, labels, conditions) -> list[list[str]]:
    rows = []
    for sizes, text, needs, value, ok, describe in conditions:
        for label in (labels if sizes is None else sizes):
            rows.append([text, label, *_every(results, label, labels, needs, value, ok, describe)])
    return rows


def _speed_rows(results, labels, size, system) -> list[list[str]]:
    """The speed targets of `system` at `size` (figures.SPEED_TARGETS), geometric means over the surfaces."""
    rows = []
    for at, a, b, target in fig.SPEED_TARGETS:
        if (at, a) != (size, system):
            continue
        name = next(n for n, x, y, _ in fig.RATIOS if (x, y) == (a, b))
        text = f"{name} (vertices/s, geometric mean) >= {target:g}"
        if size not in labels:
            rows.append([text, size, NA, f"not measured (no {size} run)"])
            continue
        v = fig.ratio_means(results, size)[(a, b)]
        rows.append([text, size, _status(None if v is None else v >= target), _fmt(v, ".3g", "×")])
    return rows


def default_quality(spec, group) -> tuple[str, str]:
    """The quality targets docs/quality.md checks (quality_report/targets.py), on the default mesh."""
    checks = quality_targets.check(spec, [(group.label, {"projection": group.runs.get(D),
                                                         "cgal": group.runs.get("cgal")})])
    kept = [(name, status) for name, status, _ in checks if name.startswith(fig.QUALITY_TARGET_NAMES)]
    failed = [name.split(" (")[0] for name, status in kept if status == NOT_MET]
    return (NOT_MET if failed else MET), ("; ".join(failed) if failed else "all met")


def _docs_quality_rows(results, labels) -> list[list[str]]:
    """The quality targets of docs/quality.md on the default mesh: at 20k (issue 34), and at every other
    measured size."""
    rows = []
    for label in dict.fromkeys([fig.SMALL_SIZE, *labels]):
        text = "default: the quality targets of docs/quality.md"
        if label not in labels:
            rows.append([text, label, NA, f"not measured (no {label} run)"])
            continue
        statuses = [(spec.name, default_quality(spec, g)) for spec, _, gs in results for g in gs
                    if g.label == label and g.runs.get(D) is not None]
        bad = [f"{n}: {why}" for n, (s, why) in statuses if s != MET]
        rows.append([text, label, NOT_MET if bad else (MET if statuses else NA),
                     f"{len(statuses) - len(bad)} of {len(statuses)} surfaces meet all" + (
                         " (not met: " + "; ".join(bad) + ")" if bad else "")])
    return rows


def _large_rows(results, large, labels) -> list[list[str]]:
    """The ~1M-vertex targets on the large run (figures.large_figures)."""
    f = fig.large_figures(results, large, labels)
    ok = large is not None and large.ok
    what = f"~1M vertices, default ({fig.LARGE_SURFACE}" + (f", {large.vertices} vertices)" if ok else ")")
    fe = getattr(large, "fe", None) if ok else None
    fe_detail = (f" (Flying Edges {fe.vertices} vertices, {fe.knob})" if fe is not None and fe.ok else
                 "not measured (no Flying Edges run at this count)" if fe is None else f" (Flying Edges: {fe.error})")
    missing = "not run (--large 0)" if large is None else ("" if ok else f"failed: {large.error}")
    reference = f"the {f['label']} case's" + (
        "" if f["label"] == fig.TARGET_SIZE else f" (no {fig.TARGET_SIZE} size in this run)" if fig.TARGET_SIZE
        not in labels else f" (this run's reference; the target compares with the {fig.TARGET_SIZE} case)")
    figures = [
        (f"{what}: as fast as VTK Flying Edges at the same vertex count (vertices/s ratio >= "
         f"{fig.TARGET_LARGE_FE:g})", f["fe"], lambda v: v >= fig.TARGET_LARGE_FE,
         fe_detail if fe is None else _fmt(f["fe"], ".3g", "×") + fe_detail),
        (f"{what}: peak memory <= {fig.TARGET_BYTES:g} bytes per output vertex", f["bytes"],
         lambda v: v <= fig.TARGET_BYTES, _fmt(f["bytes"], ".0f", " B")),
        (f"{what}: time per vertex <= {fig.TARGET_LARGE_TIME:g}× {reference}", f["time"],
         lambda v: v <= fig.TARGET_LARGE_TIME, _fmt(f["time"], ".2f", "×")),
    ]
    return [[text, "large", _status(None if v is None else ok_(v)), missing or measured]
            for text, v, ok_, measured in figures]


def target_rows(results, large, labels) -> list[list[str]]:
    """[target, size, status, measured] for every target of issue 34, in the issue's order."""
    return (_speed_rows(results, labels, fig.TARGET_SIZE, D) + _condition_rows(results, labels, DEFAULT_CONDITIONS) +
            _speed_rows(results, labels, fig.TARGET_SIZE, P) + _condition_rows(results, labels, PREVIEW_CONDITIONS) +
            _large_rows(results, large, labels) + _speed_rows(results, labels, fig.SMALL_SIZE, D) +
            _docs_quality_rows(results, labels) + _condition_rows(results, labels, FINE_CONDITIONS) +
            _condition_rows(results, labels, EVERY_SIZE_CONDITIONS))
