"""Running the three systems and the analyser: one function per tool, failures captured, never raised.

Every function returns a Run; a failed or timed-out command gives ok=False with the reason, so the
report can show a row saying so instead of aborting.
"""

import json
import re
import subprocess
import sys
import time
from dataclasses import dataclass, field

MESH_TIMEOUT_S = 180  # projection and marching cubes, one run
CGAL_TIMEOUT_S = 240  # one CGAL run
ANALYZE_TIMEOUT_S = 180


@dataclass
class Run:
    system: str  # "projection", "mc" or "cgal"
    knob: str  # the size parameter that produced it, e.g. "h 0.05", "grid 64", "R 0.05"
    value: float  # the numeric value of the knob
    ok: bool = False
    vertices: int | None = None
    ms: float | None = None  # meshing wall time reported by the tool (no file output)
    mesh: str | None = None
    error: str | None = None
    timings: list[float] = field(default_factory=list)  # every timed repetition, ms
    analysis: dict | None = None
    analysis_error: str | None = None
    ideal: dict | None = None  # isopatch_ideal_lattice --json on this mesh (projection meshes only)


def log_attempt(run: Run) -> None:
    """One line on stderr per attempt, so that a slow or odd fit can be followed."""
    what = f"{run.vertices} vertices, {run.ms:.1f} ms" if run.ok else f"failed: {run.error}"
    print(f"[quality]    try {run.system:10s} {run.knob:18s} {what}", file=sys.stderr, flush=True)


def run_command(args: list[str], timeout: float) -> tuple[int | None, str, str]:
    """Runs args; returns (exit code or None on timeout/launch failure, stdout, stderr or reason)."""
    try:
        p = subprocess.run(args, capture_output=True, text=True, timeout=timeout, check=False)
        return p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {timeout:.0f} s"
    except OSError as e:
        return None, "", f"could not start {args[0]}: {e}"


def _failure(run: Run, code: int | None, err: str) -> Run:
    lines = [line for line in err.strip().splitlines() if line.strip()]
    reason = lines[-1] if lines else "no message"
    run.error = reason if code is None else f"exit {code}: {reason}"
    return run


def _summary_field(stdout: str, key: str) -> str | None:
    m = re.search(rf"^{key}\s+(\S+)", stdout, re.MULTILINE)
    return m.group(1) if m else None


def isopatch_mesh(tool: str, surface: list[str], extra: list[str], out: str, run: Run) -> Run:
    """`isopatch mesh SURFACE EXTRA -o OUT`; vertices and the mesher's time (its `meshing` line; `time` is the
    whole run) from its summary."""
    code, stdout, err = run_command([tool, "mesh", *surface, *extra, "-o", out], MESH_TIMEOUT_S)
    if code != 0:
        return _failure(run, code, err)
    vertices = _summary_field(stdout, "vertices")
    seconds = _summary_field(stdout, "meshing")
    if vertices is None or seconds is None:
        return _failure(run, 1, "no 'vertices' or 'meshing' line in the summary of isopatch mesh")
    run.ok, run.vertices, run.mesh = True, int(vertices.replace(",", "")), out
    depth, resolution = _summary_field(stdout, "depth"), _summary_field(stdout, "resolution")
    if run.system == "projection" and depth and resolution:
        run.knob += f" (d {depth}, r {resolution})"
    run.timings.append(1e3 * float(seconds))
    run.ms = min(run.timings)
    return run


def projection(tool: str, surface: list[str], h: float, out: str) -> Run:
    run = Run("projection", f"h {h:.4g}", h)
    return isopatch_mesh(tool, surface, ["--edge-length", repr(h)], out, run)


def projection_default(tool: str, surface: list[str], out: str) -> Run:
    return isopatch_mesh(tool, surface, [], out, Run("projection", "default h", 0.0))


def marching_cubes(tool: str, surface: list[str], grid: int, out: str) -> Run:
    run = Run("mc", f"grid {grid}", grid)
    return isopatch_mesh(tool, surface, ["--method", "mc", "--grid", str(grid)], out, run)


def cgal(peer: str, surface: list[str], radius: float, out: str) -> Run:
    """The CGAL peer (bench/cgal_surface_mesher.cpp) with radius bound `radius`."""
    run = Run("cgal", f"R {radius:.4g}", radius)
    code, stdout, err = run_command([peer, *surface, "--radius", repr(radius), "-o", out, "--json"], CGAL_TIMEOUT_S)
    if code != 0:
        return _failure(run, code, err)
    try:
        data = json.loads(stdout.strip().splitlines()[-1])
        run.ok, run.vertices, run.mesh = True, int(data["vertices"]), out
        run.timings.append(float(data["ms"]))
        run.ms = min(run.timings)
    except (ValueError, KeyError, IndexError) as e:
        return _failure(run, 1, f"unreadable JSON from the CGAL peer: {e}")
    return run


def repeat_timing(run: Run, again) -> None:
    """Adds the time of `again()` (a fresh Run of the same configuration) to run; keeps the minimum."""
    other = again()
    if other.ok and other.vertices == run.vertices:
        run.timings.extend(other.timings)
        run.ms = min(run.timings)


def analyze(tool: str, run: Run, surface: list[str]) -> None:
    """Fills run.analysis with `isopatch analyze MESH --surface ... --json`."""
    if not run.ok:
        return
    args = [tool, "analyze", run.mesh, "--surface", surface[0], *surface[1:], "--json"]
    code, stdout, err = run_command(args, ANALYZE_TIMEOUT_S)
    if code != 0:
        _failure(run, code, err)
        run.analysis_error, run.error = run.error, None
        return
    try:
        run.analysis = json.loads(stdout)
    except ValueError as e:
        run.analysis_error = f"unreadable analysis JSON: {e}"


def ideal_lattice(tool: str, run: Run, surface: list[str], sizes: str) -> None:
    """Fills run.ideal with `isopatch_ideal_lattice MESH --surface ... --sizes SIZES --json`: the H nRMS
    of ideal equilateral rings at the mesh's vertex count (bench/ideal_lattice). Left None on failure."""
    if not (tool and run.ok and run.mesh):
        return
    args = [tool, run.mesh, "--surface", surface[0], *surface[1:], "--sizes", sizes, "--json"]
    code, stdout, err = run_command(args, ANALYZE_TIMEOUT_S)
    if code != 0:
        print(f"[quality]    ideal lattice failed: {err.strip()}", file=sys.stderr, flush=True)
        return
    try:
        run.ideal = json.loads(stdout.strip().splitlines()[-1])
    except (ValueError, IndexError) as e:
        print(f"[quality]    unreadable ideal-lattice JSON: {e}", file=sys.stderr, flush=True)


def now() -> float:
    return time.monotonic()
