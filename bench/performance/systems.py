"""Running the systems of the performance report, one function each; failures captured, never raised.

isopatch and CGAL's Surface_mesher go through quality_report/runs.py; this module adds the VTK
Flying Edges peer, the CGAL isotropic-remeshing peer, `--stats-json`, peak memory and file hashes.
"""

import hashlib
import json
import os
import re
import resource
from dataclasses import dataclass, field

import runs

PEER_TIMEOUT_S = 600  # one Flying Edges or remeshing run (200k vertices and more)
LARGE_TIMEOUT_S = 1800  # the 1M-vertex isopatch run


@dataclass
class Timed(runs.Run):
    """A Run with what the performance report adds."""
    quality: str = ""  # isopatch --quality
    threads: int = 0  # threads the system was given
    stats: dict | None = None  # isopatch --stats-json (the last repetition's)
    stage_ms: dict = field(default_factory=dict)  # per-stage wall times when a system reports them
    value_evaluations: int | None = None
    gradient_evaluations: int | None = None
    sha256: str | None = None  # of the mesh file
    max_rss_kb: int | None = None  # peak resident memory of the whole process (/usr/bin/time -v)
    input_ms: list[float] = field(default_factory=list)  # FE + remesh: the Flying Edges times
    input_vertices: int | None = None
    notes: list[str] = field(default_factory=list)  # oddities seen while measuring
    reference: "Timed | None" = None  # the large run: the small run of the same surface timed around it
    fe: "Timed | None" = None  # the large run: VTK Flying Edges fitted to its vertex count
    cpu_ms: list[float] = field(default_factory=list)  # user + system time of each timed process, whole run


def _children_cpu_ms() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return 1e3 * (usage.ru_utime + usage.ru_stime)


def _with_cpu(make):
    """Wraps a function that runs one child process and returns a Timed: records the child's CPU time
    (user + system of the whole process, files included), a load-independent cross-check of wall times."""
    def wrapped(*args, **kwargs):
        before = _children_cpu_ms()
        run = make(*args, **kwargs)
        if run.ok:
            run.cpu_ms.append(_children_cpu_ms() - before)
        return run
    wrapped.__doc__ = make.__doc__
    return wrapped


def digest(path: str | None) -> str | None:
    if not path or not os.path.exists(path):
        return None
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _stage_times(stats: dict) -> dict:
    """{stage/name: ms} for every entry of a --stats-json that reads as a time: any entry of a stage
    whose name speaks of times ("times", "stage_seconds", ...; seconds unless it ends in "ms"), and
    elsewhere an entry named seconds, *_seconds, *_s (seconds) or *_ms (milliseconds)."""
    out = {}
    for stage, entries in stats.items():
        if not isinstance(entries, dict):
            continue
        timing_stage = any(word in stage for word in ("time", "second", "stage"))
        for name, value in entries.items():
            if not isinstance(value, (int, float)) or (stage == "mesh" and name == "seconds"):
                continue
            if timing_stage:
                in_ms = stage.endswith("ms") or name.endswith("_ms")
                out[f"{stage}/{name}"] = float(value) * (1.0 if in_ms else 1e3)
            elif name == "seconds" or name.endswith("_seconds") or name.endswith("_s"):
                out[f"{stage}/{name}"] = 1e3 * float(value)
            elif name.endswith("_ms") or name == "ms":
                out[f"{stage}/{name}"] = float(value)
    return out


def read_stats(run: Timed, path: str) -> None:
    """Fills the evaluation counts and stage times from isopatch's --stats-json file, when present."""
    try:
        with open(path, encoding="utf-8") as f:
            run.stats = json.load(f)
    except (OSError, ValueError):
        return
    mesh = run.stats.get("mesh", {}) if isinstance(run.stats.get("mesh"), dict) else {}
    run.value_evaluations = mesh.get("value_evaluations")
    run.gradient_evaluations = mesh.get("gradient_evaluations")
    run.stage_ms = _stage_times(run.stats)


RAW = "raw"  # not a preset: the paper's method alone, `--refine 1 --remesh 0` (no clean-up at all)
PIPELINE = "pipeline"  # not a preset: the default without multiresolution, `--refine 1` (the whole-mesh clean-up)
FINE_PIPELINE = "fine pipeline"  # not a preset: fine without multiresolution, `--quality fine --refine 1`


def quality_arguments(quality: str) -> list[str]:
    """The command-line arguments of a preset name, of RAW (the default's partition and patches with
    the clean-up switched off), of PIPELINE (the default at one level: patches and clean-up) or of
    FINE_PIPELINE (fine at one level)."""
    if quality == RAW:
        return ["--quality", "default", "--refine", "1", "--remesh", "0"]
    if quality == PIPELINE:
        return ["--quality", "default", "--refine", "1"]
    if quality == FINE_PIPELINE:
        return ["--quality", "fine", "--refine", "1"]
    return ["--quality", quality]


@_with_cpu
def isopatch(tool: str, surface: list[str], h: float, quality: str, threads: int, out: str) -> Timed:
    """`isopatch mesh SURFACE --edge-length h --quality Q --threads T --stats-json ...` (Q may be RAW)."""
    run = Timed(f"isopatch {quality}", f"h {h:.4g}", h, quality=quality, threads=threads)
    stats = out + ".stats.json"
    extra = ["--edge-length", repr(h), *quality_arguments(quality), "--threads", str(threads), "--stats-json", stats]
    runs.isopatch_mesh(tool, surface, extra, out, run)
    if run.ok:
        read_stats(run, stats)
        run.sha256 = digest(out)
    return run


def isopatch_peak_memory(tool: str, surface: list[str], h: float, threads: int, out: str) -> Timed:
    """The same as isopatch(..., "default", ...) under `/usr/bin/time -v`, for the peak resident memory."""
    run = Timed("isopatch default", f"h {h:.4g}", h, quality="default", threads=threads)
    stats = out + ".stats.json"
    args = ["/usr/bin/time", "-v", tool, "mesh", *surface, "--edge-length", repr(h), "--quality", "default",
            "--threads", str(threads), "--stats-json", stats, "-o", out]
    code, _, err = runs.run_command(args, LARGE_TIMEOUT_S)
    if code != 0:
        return runs._failure(run, code, err)
    read_stats(run, stats)
    mesh = (run.stats or {}).get("mesh", {})
    rss = re.search(r"Maximum resident set size \(kbytes\):\s*(\d+)", err)
    if "vertices" not in mesh or "seconds" not in mesh or rss is None:
        return runs._failure(run, 1, "no vertex count, time or peak memory from the 1M-vertex run")
    run.ok, run.vertices, run.mesh = True, int(mesh["vertices"]), out
    run.timings.append(1e3 * float(mesh["seconds"]))
    run.ms = min(run.timings)
    run.max_rss_kb = int(rss.group(1))
    return run


def cgal(peer: str, surface: list[str], radius: float, out: str) -> Timed:
    """CGAL's Surface_mesher peer (quality_report/runs.py) as a Timed run."""
    return Timed(**vars(runs.cgal(peer, surface, radius, out)))


cgal = _with_cpu(cgal)


def _json_line(stdout: str) -> dict:
    return json.loads(stdout.strip().splitlines()[-1])


@_with_cpu
def flying_edges(peer: str, surface: list[str], grid: int, threads: int, out: str) -> Timed:
    """isopatch_vtk_peer: grid sampling (batch evaluation) and vtkFlyingEdges3D, timed together."""
    run = Timed("vtk fe", f"grid {grid}", grid, threads=threads)
    code, stdout, err = runs.run_command([peer, *surface, "--grid", str(grid), "--threads", str(threads), "-o", out,
                                          "--json"], PEER_TIMEOUT_S)
    if code != 0:
        return runs._failure(run, code, err)
    try:
        data = _json_line(stdout)
        run.ok, run.vertices, run.mesh = True, int(data["vertices"]), out
        run.timings.append(float(data["ms"]))
        run.ms = min(run.timings)
        run.value_evaluations, run.gradient_evaluations = int(data["value_evaluations"]), 0
        run.stage_ms = {k: float(data[k]) for k in ("sample_ms", "contour_ms", "convert_ms")}
    except (ValueError, KeyError, IndexError) as e:
        return runs._failure(run, 1, f"unreadable JSON from the VTK peer: {e}")
    return run


@_with_cpu
def remesh(remesher: str, fe: Timed, edge: float | None, vertices: int, out: str) -> Timed:
    """isopatch_cgal_remesh on the Flying Edges mesh `fe`: target edge `edge`, or from `vertices` when
    None. The run's time is Flying Edges' plus the remeshing's (both minima over repetitions)."""
    knob = f"edge {edge:.4g}" if edge else f"~{vertices} v"
    run = Timed("fe + remesh", knob, edge or 0.0, threads=1)
    size = ["--edge-length", repr(edge)] if edge else ["--vertices", str(vertices)]
    code, stdout, err = runs.run_command([remesher, fe.mesh, *size, "--iterations", "5", "-o", out, "--json"],
                                         PEER_TIMEOUT_S)
    if code != 0:
        return runs._failure(run, code, err)
    try:
        data = _json_line(stdout)
        run.ok, run.vertices, run.mesh = True, int(data["vertices"]), out
        run.value, run.knob = float(data["target_edge"]), f"edge {float(data['target_edge']):.4g}"
        run.input_vertices = fe.vertices
        run.stage_ms = {"remesh_ms": float(data["ms"])}
        run.timings.append(float(data["ms"]))
        run.input_ms = fe.timings
        run.ms = min(run.timings) + min(fe.timings)
        run.value_evaluations = fe.value_evaluations
        run.gradient_evaluations = 0
    except (ValueError, KeyError, IndexError) as e:
        return runs._failure(run, 1, f"unreadable JSON from the remeshing peer: {e}")
    return run


COUNT_TOLERANCE = 0.02  # a repetition whose count differs by less (CGAL's random start) is scaled to it


def add_timing(run: Timed, other: Timed) -> None:
    """Adds a repetition's time to run (same configuration); keeps the minimum. A repetition with a
    slightly different vertex count (CGAL's Surface_mesher starts from random points) counts with its
    time scaled to run's count; one further off is left out, with a note."""
    if not (run.ok and other.ok and other.vertices):
        return
    scale = run.vertices / other.vertices
    if abs(scale - 1.0) > COUNT_TOLERANCE:
        run.notes.append(f"a repetition gave {other.vertices} vertices: left out")
        return
    run.timings.extend(t * scale for t in other.timings)
    run.cpu_ms.extend(t * scale for t in other.cpu_ms)
    if run.system == "fe + remesh":
        run.ms = min(run.timings) + min(run.input_ms)
    else:
        run.ms = min(run.timings)
    if other.sha256 and run.sha256 and other.sha256 != run.sha256:
        run.notes.append("output bytes differ between repetitions")
