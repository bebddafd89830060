"""The figures of the performance report from the measured groups: speeds, ratios, geometric means,
the large mesh's figures and the thresholds of issue 34's targets (issue_targets.py checks them)."""

import math

import targets as quality_targets
from metrics import metrics

MET, NOT_MET, NA = quality_targets.MET, quality_targets.NOT_MET, quality_targets.NA

TARGET_SIZE = "200k"  # the size most of its targets are at (and the large run's reference)
SMALL_SIZE = "20k"
SPEED_TARGETS = [  # (size, system, peer, vertices per second of system over peer's, geometric mean)
    (TARGET_SIZE, "default 2t", "fe", 0.25),
    (TARGET_SIZE, "default 2t", "cgal", 50.0),
    (TARGET_SIZE, "default 2t", "fe + remesh", 20.0),
    (TARGET_SIZE, "preview", "fe", 0.5),
    (SMALL_SIZE, "default 2t", "cgal", 10.0),
]
DEFAULT_VALENCE6 = 0.97  # default at 200k, every surface
DEFAULT_ANGLE = 25.0
DEFAULT_H_CGAL = 0.1  # default's H nRMS over CGAL's
DEFAULT_H_ONE_LEVEL = 1.0  # default's H nRMS over the one-level pipeline's (--refine 1)
PREVIEW_VALENCE6 = 0.95  # preview at 200k, every surface
PREVIEW_ANGLE = 20.0
PREVIEW_H_CGAL = 1.0
FINE_H_ONE_LEVEL = 0.5  # fine's H nRMS over fine at one level's, every surface, every size
TARGET_LARGE_FE = 1.0  # the large run's vertices/s over Flying Edges' at the same count
TARGET_LARGE_TIME = 1.2  # time per vertex of the large run over the reference size's
TARGET_BYTES = 150.0  # peak memory per output vertex of the large run
TARGET_GRADIENTS = 10.0  # evaluations of grad f per output vertex (the aim)
LARGE_SURFACE = "sphere"
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


def target_text(system, peer) -> str:
    """The ratio table's target of `system` ÷ `peer`: every size's threshold, e.g. ">= 50 (200k), >= 10 (20k)"."""
    found = [f">= {t:g} ({size})" for size, s, p, t in SPEED_TARGETS if (s, p) == (system, peer)]
    return ", ".join(found) if found else "–"


def speed_target(label, system, peer) -> float | None:
    """The ratio `system` ÷ `peer` issue 34 asks for at size `label`, None when it asks for none."""
    return next((t for size, s, p, t in SPEED_TARGETS if (size, s, p) == (label, system, peer)), None)


RATIOS = [(name, a, b, target_text(a, b)) for name, a, b in [  # (name, numerator, denominator, target text)
    ("isopatch default ÷ VTK Flying Edges", "default 2t", "fe"),
    ("isopatch default ÷ CGAL Surface_mesher", "default 2t", "cgal"),
    ("isopatch default ÷ FE + isotropic remeshing", "default 2t", "fe + remesh"),
    ("isopatch preview ÷ VTK Flying Edges", "preview", "fe"),
    ("isopatch default, 2 threads ÷ 1 thread", "default 2t", "default 1t"),
    ("isopatch fine ÷ CGAL Surface_mesher", "fine", "cgal"),
    ("isopatch preview ÷ CGAL Surface_mesher", "preview", "cgal"),
    ("the paper's method alone (isopatch --remesh 0) ÷ CGAL Surface_mesher", "raw", "cgal"),
    ("the paper's method alone ÷ FE + isotropic remeshing", "raw", "fe + remesh"),
    ("the paper's method alone ÷ VTK Flying Edges", "raw", "fe"),
]]

BUDGETS = list(dict.fromkeys((s, p) for _, s, p, _ in SPEED_TARGETS))  # (system, peer) of each speed target


def allowed_ms(group, system, peer, target) -> float | None:
    """The wall time (ms) a speed target allows `system` for its own vertex count: that count at
    `target` times the peer's vertices per second."""
    run, v = group.runs.get(system), speed(group.runs.get(peer))
    ok = run is not None and run.ok and run.vertices and v and target
    return 1e3 * run.vertices / (target * v) if ok else None


def raw_ms_at(group, system) -> float | None:
    """The time the paper's method alone (no clean-up) takes for as many vertices as `system` made, at
    its own vertices per second: the part of the budget the clean-up cannot have."""
    run, v = group.runs.get(system), speed(group.runs.get("raw"))
    return 1e3 * run.vertices / v if run is not None and run.ok and run.vertices and v else None


def group_ratio(group, a, b) -> float | None:
    return ratio(speed(group.runs.get(a)), speed(group.runs.get(b)))


def ratio_means(results, label) -> dict:
    """{(a, b): geometric mean over the surfaces of speed(a) / speed(b)} at size `label`."""
    pairs = {(a, b) for _, a, b, _ in RATIOS} | set(BUDGETS)
    return {(a, b): gmean(group_ratio(g, a, b) for _, _, groups in results for g in groups if g.label == label)
            for a, b in pairs}


def reference_label(labels) -> str:
    """The size whose default run the large run's time per vertex is compared with: 200k when it was
    measured, else the largest measured size."""
    return TARGET_SIZE if TARGET_SIZE in labels else labels[-1]


def _large_surface_runs(results):
    """[(size label, default 2t run)] of the large run's surface."""
    return [(g.label, g.runs.get("default 2t")) for spec, _, groups in results if spec.name == LARGE_SURFACE
            for g in groups]


def _reference(results, large, labels):
    """(size label, small run) the large run's time per vertex is compared with: the run timed around
    the large run (its size the one whose default run has the same edge length) when there is one,
    else the large surface's default run at reference_label(labels)."""
    small = getattr(large, "reference", None)
    own = _large_surface_runs(results)
    if small is not None and small.ok:
        label = next((lb for lb, r in own if r is not None and r.ok and math.isclose(r.value, small.value)),
                     reference_label(labels))
        return label, small
    label = reference_label(labels)
    return label, next((r for lb, r in own if lb == label), None)


def large_figures(results, large, labels) -> dict:
    """The large run's figures: "time" its time per vertex over that of the reference size ("label",
    see _reference), "bytes" its peak memory per output vertex, "fe" its vertices per second over
    those of Flying Edges at the same count (large.fe); None where not measured."""
    label, small = _reference(results, large, labels)
    out = {"label": label, "time": None, "bytes": None, "fe": None}
    if large is None or not large.ok:
        return out
    per_v = lambda r: r.ms / r.vertices if r is not None and r.ok and r.ms else None  # noqa: E731
    out["time"] = ratio(per_v(large), per_v(small))
    out["bytes"] = 1024.0 * large.max_rss_kb / large.vertices if large.max_rss_kb else None
    out["fe"] = ratio(speed(large), speed(getattr(large, "fe", None)))
    return out


def _fmt(x, spec=".3g", suffix="") -> str:
    return "–" if x is None else format(x, spec) + suffix
