"""docs/performance.md from the measured groups: ratios first, then the targets of issue 34, the
per-surface tables, the large mesh, where isopatch's time goes, and how it was measured."""

import figures as fig
import issue_targets
import machine
import runs
from markdown import _table
from figures import _fmt

SPEED_SYSTEMS = [("default 2t", "default 2t"), ("default 1t", "default 1t"), ("preview", "preview 2t"),
                 ("fine", "fine 2t"), ("pipeline", "one level (--refine 1) 2t"), ("raw", "paper's method alone 2t"),
                 ("cgal", "CGAL"), ("fe", "FE 2t"), ("fe + remesh", "FE + remesh")]
QUALITY_SYSTEMS = [("default 2t", "isopatch default"), ("preview", "isopatch preview"), ("fine", "isopatch fine"),
                   ("pipeline", "isopatch at one level (--refine 1: patches and the whole-mesh clean-up)"),
                   ("fine pipeline", "isopatch fine at one level (--quality fine --refine 1; run once, quality only)"),
                   ("raw", "isopatch, the paper's method alone (--refine 1 --remesh 0)"),
                   ("cgal", "CGAL Surface_mesher"), ("fe", "VTK Flying Edges"), ("fe + remesh", "FE + isotropic remeshing")]


def _version(tool: str) -> str:
    code, stdout, _ = runs.run_command([tool, "--version"], 30)
    return stdout.strip() if code == 0 and stdout.strip() else "version unknown"


def tool_lines(args, loads) -> list[str]:
    """Header lines beyond the quality report's: the peers, the load during the run, the binary."""
    fe = f"{machine.debian_version('libvtk9-dev', 'VTK')}, vtkFlyingEdges3D" if args.vtk else "not built (VTK not found): FE rows say so"
    remesh = "CGAL Polygon_mesh_processing::isotropic_remeshing, 5 rounds" if args.remesh else "not built"
    return [f"- Flying Edges: {fe}; remeshing: {remesh}",
            f"- isopatch binary: `{args.tool}` ({_version(args.tool)}); timed runs per system: {args.repeats} "
            "(minimum kept)",
            f"- load average (1 min) sampled between surfaces: {min(loads):.2f} to {max(loads):.2f}"]


def _ratio_table(results, labels, large) -> str:
    means = {label: fig.ratio_means(results, label) for label in labels}
    rows = [[name, target] + [_fmt(means[label][(a, b)], ".3g", "×") for label in labels]
            for name, a, b, target in fig.RATIOS]
    large_rows = fig.large_figures(results, large, labels)
    blank = [""] * (len(labels) - 1)
    rows.append(["1M-vertex mesh: isopatch default ÷ VTK Flying Edges at the same vertex count",
                 f">= {fig.TARGET_LARGE_FE:g}", _fmt(large_rows["fe"], ".3g", "×"), *blank])
    rows.append([f"1M-vertex mesh: time per vertex ÷ the {large_rows['label']} case's ({fig.LARGE_SURFACE})",
                 f"<= {fig.TARGET_LARGE_TIME:g}", _fmt(large_rows["time"], ".2f", "×"), *blank])
    rows.append(["1M-vertex mesh: peak memory per output vertex", f"<= {fig.TARGET_BYTES:g} B",
                 _fmt(large_rows["bytes"], ".0f", " B"), *blank])
    for key, what, target in (("value_evaluations", "f", "reported"),
                              ("gradient_evaluations", "grad f", f"<= {fig.TARGET_GRADIENTS:g} (the aim)")):
        row = [f"evaluations of {what} per output vertex (isopatch default)", target]
        for label in labels:
            row.append(_fmt(fig.gmean(fig.per_vertex(getattr(g.runs.get("default 2t"), key, None), g.runs.get("default 2t"))
                                      for _, _, gs in results for g in gs if g.label == label), ".3g"))
        rows.append(row)
    header = ["figure (a ratio: vertices per second of the first over the second, geometric mean over the surfaces)",
              "target"] + labels
    return _table(header, ["l", "l"] + ["r"] * len(labels), rows)


def _speed_table(results, label) -> str:
    header = ["surface", "vertices"] + [f"{shown} v/s" for _, shown in SPEED_SYSTEMS] + [
        "default ÷ CGAL", "default ÷ FE+remesh", "preview ÷ FE", "2t ÷ 1t", "same bytes 1/2/4 t"]
    rows = []
    for spec, _, groups in results:
        for g in groups:
            if g.label != label:
                continue
            d = g.runs.get("default 2t")
            same = fig.identical(g)
            rows.append([spec.name, _fmt(getattr(d, "vertices", None), "d")] +
                        [_speed_cell(g.runs.get(name)) for name, _ in SPEED_SYSTEMS] +
                        [_fmt(fig.group_ratio(g, "default 2t", "cgal"), ".3g", "×"),
                         _fmt(fig.group_ratio(g, "default 2t", "fe + remesh"), ".3g", "×"),
                         _fmt(fig.group_ratio(g, "preview", "fe"), ".3g", "×"), _fmt(fig.speedup(g), ".2f", "×"),
                         "–" if same is None else ("yes" if same else "**no**")])
    return _table(header, ["l", "r"] + ["r"] * (len(header) - 2), rows)


def _speed_cell(run) -> str:
    if run is None:
        return "–"
    if not run.ok:
        return f"failed: {run.error}"
    v = fig.speed(run)
    if v is None:
        return "–"
    return (f"{v / 1e6:.3g}M" if v >= 1e6 else f"{v / 1e3:.3g}k") + f" ({run.vertices})"


def _quality_table(results, label) -> str:
    header = ["surface", "system", "knob", "vertices", "ms (min of n)", "CPU ms", "% val 6", "min ∠", "H nRMS", "H ÷ CGAL",
              "max vert dist", "f evals / v", "grad evals / v"]
    rows = []
    for spec, _, groups in results:
        for g in groups:
            if g.label != label:
                continue
            cgal_h = (fig.quality(g.runs.get("cgal")) or {}).get("h_nrms")
            for name, shown in QUALITY_SYSTEMS:
                run = g.runs.get(name)
                if run is None or not run.ok:
                    rows.append([spec.name, shown, "", f"failed: {run.error}" if run else "not run"] + ["–"] * 9)
                    continue
                m = fig.quality(run) or {}
                ms = f"{run.ms:.1f} ({len(run.timings)})"
                cpu = _fmt(min(run.cpu_ms), ".1f") if getattr(run, "cpu_ms", None) else "–"
                rows.append([spec.name, shown, run.knob, str(run.vertices), ms, cpu,
                             _fmt(None if m.get("valence6") is None else 100 * m["valence6"], ".1f"),
                             _fmt(m.get("min_angle"), ".1f"), _fmt(m.get("h_nrms"), ".3g"),
                             _fmt(fig.ratio(m.get("h_nrms"), cgal_h), ".3g"), _fmt(m.get("vertex_distance"), ".1e"),
                             _fmt(fig.per_vertex(getattr(run, "value_evaluations", None), run), ".3g"),
                             _fmt(fig.per_vertex(getattr(run, "gradient_evaluations", None), run), ".3g")])
    return _table(header, ["l", "l", "l"] + ["r"] * 10, rows)


def _stage_section(results, labels) -> list[str]:
    """Per-stage times of isopatch default (2 threads) when its --stats-json gives any."""
    rows, names = [], []
    for spec, _, groups in results:
        for g in groups:
            d = g.runs.get("default 2t")
            if d is not None and d.ok and d.stage_ms:
                names += [n for n in d.stage_ms if n not in names]
                rows.append((spec.name, g.label, d))
    out = ["## Where isopatch's time goes (default, 2 threads)", ""]
    if not rows:
        return out + ["The `--stats-json` of this binary reports no per-stage times (only the whole mesh's "
                      "`seconds`), so there is no breakdown here yet.", ""]
    table = [[n, label, _fmt(d.ms, ".1f")] + [_fmt(d.stage_ms.get(k), ".1f") for k in names] for n, label, d in rows]
    out += ["Stage times in ms as isopatch's `--stats-json` reports them (last timed repetition).", "",
            _table(["surface", "size", "total ms"] + names, ["l", "l"] + ["r"] * (len(names) + 1), table), ""]
    return out


def _budget_cells(g, system, peers) -> list[str]:
    """The budget table's cells of one system in one group: its time, what each speed target at the
    group's size allows, the paper's method alone at its count."""
    cells = [_fmt(getattr(g.runs.get(system), "ms", None), ".1f")]
    for peer in peers:
        target = fig.speed_target(g.label, system, peer)
        cells.append(_fmt(fig.allowed_ms(g, system, peer, target), ".1f") + ("" if target is None else
                                                                             f" (>= {target:g})"))
    return cells + [_fmt(fig.raw_ms_at(g, system), ".1f")]


def _budget_section(results, labels) -> list[str]:
    """What each speed target allows in wall time, next to the time of the paper's method alone for the
    same vertex count: the clean-up can only have the difference."""
    out = ["## What the speed targets leave for the clean-up", "",
           "Each speed target, turned into the wall time it allows for the mesh's own vertex count (ms, 2 threads; "
           "the target of the row's size in brackets, – where none is set at that size), next to the time "
           "the paper's method alone (partition, crossings, patches, projection; `--refine 1 --remesh 0`, no "
           "clean-up and no refinement) takes for as many vertices at its own vertices per second. Where the "
           "paper's method alone needs more than a target allows, that target cannot be met by running it on the "
           "whole mesh, however cheap the clean-up after it.", ""]
    systems = list(dict.fromkeys(system for system, _ in fig.BUDGETS))  # default 2t, preview
    shown = {"default 2t": "default", "preview": "preview"}
    peers = {"cgal": "CGAL", "fe + remesh": "FE+remesh", "fe": "FE"}
    header, rows = ["surface", "size"], []
    for system in systems:
        header.append(f"{shown.get(system, system)} ms")
        header += [f"allowed by ÷ {peers.get(peer, peer)}" for s_, peer in fig.BUDGETS if s_ == system]
        header.append(f"paper's method alone, {shown.get(system, system)}'s count")
    for spec, _, groups in results:
        for g in groups:
            if g.label in labels:
                rows.append([spec.name, g.label] + [cell for system in systems for cell in _budget_cells(
                    g, system, [peer for s_, peer in fig.BUDGETS if s_ == system])])
    out += [_table(header, ["l", "l"] + ["r"] * (len(header) - 2), rows), ""]
    for label in labels:
        shares = []
        for system, peer, target in ((s_, p, fig.speed_target(label, s_, p)) for s_, p in fig.BUDGETS):
            if target is None:
                continue
            share = fig.gmean(fig.ratio(fig.raw_ms_at(g, system), fig.allowed_ms(g, system, peer, target))
                              for _, _, gs in results for g in gs if g.label == label)
            shares.append(f"{_fmt(share, '.2f', '×')} of what {shown.get(system, system)} ÷ "
                          f"{peers.get(peer, peer)} >= {target:g} allows")
        if shares:
            out.append(f"- {label}: the paper's method alone takes (geometric mean over the surfaces) " +
                       "; ".join(shares) + ".")
    return out + [""]


def _large_section(results, large, labels) -> list[str]:
    out = ["## The large mesh", ""]
    if large is None:
        return out + ["Not run (`--large 0`).", ""]
    if not large.ok:
        return out + [f"isopatch default on the {fig.LARGE_SURFACE} failed: {large.error}", ""]
    label = fig.large_figures(results, large, labels)["label"]
    return out + [f"`isopatch mesh {fig.LARGE_SURFACE} --edge-length {large.value:.4g} --threads 2` under "
                  f"`/usr/bin/time -v`: {large.vertices} vertices in {large.ms / 1e3:.1f} s "
                  f"({fig.speed(large) / 1e3:.3g}k vertices/s), peak resident memory {large.max_rss_kb / 1024:.0f} MiB "
                  f"= {1024.0 * large.max_rss_kb / large.vertices:.0f} bytes per output vertex (the whole process: "
                  "the surface, the pipeline and the mesh; writing the file included)." + _fe_text(large) +
                  _reference_text(large, label), ""]


def _fe_text(large) -> str:
    fe = getattr(large, "fe", None)
    if fe is None:
        return " No Flying Edges run at its vertex count."
    if not fe.ok:
        return f" Flying Edges at its vertex count: {fe.error}."
    return (f" VTK Flying Edges fitted to its vertex count ({fe.knob}, 2 threads, sampling included): {fe.vertices} "
            f"vertices in {fe.ms / 1e3:.2f} s ({fig.speed(fe) / 1e3:.3g}k vertices/s; minimum of "
            f"{len(fe.timings)} run{'' if len(fe.timings) == 1 else 's'}).")


def _reference_text(large, label) -> str:
    ref = getattr(large, "reference", None)
    if ref is None or not ref.ok:
        return ""
    return (f" Timed around it ({len(ref.timings)} runs just before and after, minimum kept), the "
            f"{fig.LARGE_SURFACE}'s {label} default mesh ({ref.vertices} vertices) took {ref.ms:.1f} ms "
            f"({fig.speed(ref) / 1e3:.3g}k vertices/s): the time-per-vertex ratio compares these two, made under "
            "the same load.")


TARGETS_TEXT = ("The targets of the multiresolution refinement, on 2 cores, side by side in this run: speed targets are geometric means "
                "over the surfaces of each surface's ratio at matched vertex counts, quality targets hold on every "
                "surface; `n/a` where a size or a system was not measured in this run.")

METHOD = """## How it is measured

- Surfaces: every closed public surface of the quality report (bench/quality_report/surfaces.py).
- Matched vertex counts: isopatch default on 2 threads is fitted first to about 20k (and 200k)
  vertices through its edge length (within 20%; its count moves in steps); every other system is then
  fitted to that count: preview, fine and the default at one level (`--refine 1`) by their edge length
  (within 20%), CGAL by its radius bound (within 10%), Flying Edges by its grid (within 5%), the
  remeshing by its target edge (within 5%). 1 and 4 threads use the 2-thread edge length, so their
  meshes are the same size (and should be the same bytes).
- Timing: the wall time each tool reports for meshing alone (no file output): isopatch's `--stats-json`
  `mesh.seconds`, the peers' own clocks. After the fitting, every system runs again in interleaved
  rounds (each round runs each system once), and the minimum over all timed runs is kept, so a burst of
  load from other work on the shared machine hits one repetition, not one system. The load average
  in the header tells how busy the machine was; under load a process gets less than a core, and the
  `CPU ms` column (user + system time of the whole process) shows how much of a wall time is waiting.
- Threads: isopatch `--threads 2` (and 1 for the speed-up, 4 only for the byte comparison); Flying
  Edges samples f on 2 threads (isopatch's batch evaluation, `Surface::values`, one z-slice at a time)
  and runs VTK's SMP back end on 2 threads; CGAL's Surface_mesher and isotropic remeshing are
  sequential.
- Flying Edges: the sampling of f on the grid is part of its time (cubic cells, `grid` cells along the
  box's longest side); its vertices lie on the grid edges by linear interpolation, so they are not on
  f = 0 and its evaluations per vertex are grid points per vertex.
- FE + isotropic remeshing: the matched Flying Edges mesh is remeshed by CGAL's isotropic_remeshing,
  5 rounds of edge splits and collapses, flips, tangential relaxation and projection. That projection
  is onto the Flying Edges mesh (CGAL's default), not onto f = 0: the result stays as far from the
  surface as the Flying Edges triangles are, and no evaluation of f is made after the grid. Its time is
  Flying Edges' (sampling included) plus the remeshing's (building CGAL's mesh and extracting the result
  included, file reading excluded).
- Quality: `isopatch analyze --json` on every mesh (valence 6 share of interior vertices, each
  triangle's smallest angle, H nRMS the normalized RMS error of the cotangent mean curvature, vertex
  distance the largest |f|/|grad f| at a vertex over the box diagonal); the quality targets of
  docs/quality.md are checked with the quality report's own code (bench/quality_report/targets.py).
  The quality targets of the multiresolution refinement compare, surface by surface, the default's
  H nRMS with CGAL's and with the one-level default's (`--refine 1`), both fitted to the default's
  vertex count, and fine's with fine at one level's.
- One level: isopatch `--quality default --refine 1 --threads 2`, the pipeline without multiresolution
  (the paper's patches and the clean-up of the whole mesh), fitted and timed like the other systems.
- Fine at one level: isopatch `--quality fine --refine 1 --threads 2` at the fine mesh's edge length (the
  default's when fine failed; the count comes out about the same, see the quality tables), run once and
  analysed: it is slow and only its H nRMS is compared (fine's must be at least 2× lower), so it is
  neither fitted nor repeated and its time is one run's.
- The paper's method alone: isopatch `--quality default --refine 1 --remesh 0 --threads 2` at the
  default's edge length: the partition, crossings, patches and projection, without clean-up or
  refinement. Its vertex count is lower than the default's; its vertices per second say what the
  method costs on the whole mesh.
- Same bytes: SHA-256 of the mesh files written with 1, 2 and 4 threads.
- Large mesh: isopatch default on the sphere on 2 threads, its edge length from the sphere's fits,
  run once under `/usr/bin/time -v` for the peak resident memory. Its time per vertex is compared with
  the sphere's 200k default mesh (the largest measured size when 200k is not among the sizes; the row
  names the size used) timed again 3 times just before and 3 times just after it (minimum kept), so
  that both sides of the ratio meet the same load. VTK Flying Edges is then fitted to the large mesh's
  vertex count (its grid from the sphere's earlier Flying Edges runs, V ~ c g^2, within 5%) and timed
  like at the other sizes (minimum of the repetitions): the large mesh's speed is compared with it.
- Evaluations: isopatch's `--stats-json` `mesh.value_evaluations` and `mesh.gradient_evaluations` over
  the output vertices (the targets aim at 10 or fewer evaluations of grad f per vertex); CGAL's peer does
  not count them.
- Regenerating: `bench/performance/driver.py --from-results out/performance/results.json` rebuilds the
  report from a run's results file without measuring (the header then says so)."""


def document(header_lines, results, large, sizes) -> str:
    labels = [label for label, _ in sizes]
    parts = ["# Performance report", "",
             "*Generated by `scripts/performance_report.sh`; do not edit by hand. The multiresolution refinement's targets, "
             "measured side by side in one run on one machine; how: the last section.*", ""]
    parts += header_lines
    parts += ["", "## Ratios", "",
              "isopatch's vertices per second over each peer's, geometric means over the surfaces (each surface's "
              "ratio at matched vertex counts first).", "", _ratio_table(results, labels, large), "",
              "## Targets", "", TARGETS_TEXT, "",
              _table(["target", "size", "status", "measured"], ["l", "l", "l", "l"],
                     issue_targets.target_rows(results, large, labels)), ""]
    for label in labels:
        parts += [f"## Speed per surface, about {label} vertices", "",
                  "Vertices per second (vertex count in brackets); `2t`/`1t` the threads given.", "",
                  _speed_table(results, label), ""]
    for label in labels:
        parts += [f"## Quality per surface, about {label} vertices", "",
                  "`ms (n)`: wall time, minimum of n timed runs; `CPU ms`: user + system time of the whole process "
                  "(files and start-up included; for FE + remesh the remeshing process alone), minimum over the runs; `H ÷ CGAL` H nRMS over CGAL's at the same size; "
                  "`max vert dist` the largest |f|/|grad f| at a vertex over the box diagonal.", "",
                  _quality_table(results, label), ""]
    parts += _budget_section(results, labels)
    parts += _large_section(results, large, labels)
    parts += _stage_section(results, labels)
    parts += [METHOD, ""]
    return "\n".join(parts).rstrip() + "\n"
