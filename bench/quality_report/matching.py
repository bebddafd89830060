"""Choosing each system's size knob so that the three meshes of one row group have matched vertex
counts: the projection mesh sets the count (its edge length is fitted to the nominal size), marching
cubes and CGAL are fitted to the projection's actual count.

Models: projection and CGAL V ~ c / s^2 (s the edge length or the radius bound), marching cubes
V ~ c g^2 (g the grid). One trial fixes c; each further run refits c from the closest run so far.
"""

import math
import os

import runs

PROJECTION_TOLERANCE = 0.20  # the projection's count moves in steps (octree depth, patch resolution)
MC_TOLERANCE = 0.05
CGAL_TOLERANCE = 0.10
MAX_ATTEMPTS = 3


def _closest(candidates: list[runs.Run], target: float) -> runs.Run | None:
    ok = [r for r in candidates if r.ok and r.vertices]
    return min(ok, key=lambda r: abs(math.log(r.vertices / target))) if ok else None


def _off(run: runs.Run, target: float, tolerance: float) -> bool:
    return abs(run.vertices / target - 1.0) > tolerance


def _next_size(tried: list[runs.Run], target: float) -> float:
    """The next edge length (or radius): between the closest runs on either side of the target when
    there are both (log-log interpolation; the count may jump, the bracket still narrows), else from
    the power law V ~ c / s^2 through the closest run."""
    ok = [r for r in tried if r.ok and r.vertices]
    below = [r for r in ok if r.vertices < target]
    above = [r for r in ok if r.vertices > target]
    if below and above:
        lo = min(below, key=lambda r: target / r.vertices)
        hi = min(above, key=lambda r: r.vertices / target)
        t = math.log(target / lo.vertices) / math.log(hi.vertices / lo.vertices)
        return math.exp(math.log(lo.value) + t * (math.log(hi.value) - math.log(lo.value)))
    best = _closest(ok, target)
    return best.value * math.sqrt(best.vertices / target)


def match_projection(tool, surface, target, longest_side, work, tag, known: list[runs.Run], make=None) -> runs.Run:
    """Projection mesh with about `target` vertices; the failed last attempt when none succeeds.
    `known` holds the successful runs of earlier sizes of the surface (used for the fit only) and
    receives this size's. `make(h, out)` makes one run (default: runs.projection with `--edge-length h`)."""
    make = make or (lambda h, out: runs.projection(tool, surface, h, out))
    tried = []
    if not any(r.ok for r in known):
        tried.append(make(longest_side / 64.0, os.path.join(work, f"{tag}-trial.ply")))
        runs.log_attempt(tried[-1])
    for attempt in range(MAX_ATTEMPTS + 1):
        if tried and not tried[-1].ok and len(tried) > 1:
            break
        best = _closest(tried, target)
        if best is not None and not _off(best, target, PROJECTION_TOLERANCE):
            break
        pool = [r for r in known + tried if r.ok]
        h = _next_size(pool, target) if pool else longest_side / 32.0
        if any(abs(h / r.value - 1) < 1e-3 for r in tried):
            break  # the bracket cannot narrow any more
        tried.append(make(h, os.path.join(work, f"{tag}-{attempt}.ply")))
        runs.log_attempt(tried[-1])
    known.extend(r for r in tried if r.ok)
    best = _closest(tried, target)
    return best if best is not None else tried[-1]


def match_mc(tool, surface, target, work, tag, make=None, grid=64) -> runs.Run:
    """Marching cubes with the grid whose vertex count is closest to `target`, starting at `grid`.
    `make(grid, out)` makes one run (default: runs.marching_cubes; any grid mesher with V ~ c g^2)."""
    make = make or (lambda g, out: runs.marching_cubes(tool, surface, g, out))
    tried = {}
    for attempt in range(MAX_ATTEMPTS + 1):
        if grid in tried:
            break
        run = make(grid, os.path.join(work, f"{tag}-{attempt}.ply"))
        runs.log_attempt(run)
        tried[grid] = run
        if not run.ok or (attempt > 0 and not _off(run, target, MC_TOLERANCE)):
            break
        grid = max(2, min(1024, round(grid * math.sqrt(target / run.vertices))))
    best = _closest(list(tried.values()), target)
    return best if best is not None else list(tried.values())[-1]


def match_cgal(peer, surface, target, radius, work, tag) -> runs.Run:
    """CGAL with the radius bound whose vertex count is closest to `target`, starting at `radius`."""
    tried = []
    for attempt in range(MAX_ATTEMPTS):
        run = runs.cgal(peer, surface, radius, os.path.join(work, f"{tag}-{attempt}.ply"))
        runs.log_attempt(run)
        tried.append(run)
        if run.ok and not _off(run, target, CGAL_TOLERANCE):
            break
        if run.ok:
            radius = _next_size(tried, target)
        elif "timed out" in (run.error or ""):
            radius *= 1.6  # far too many vertices: coarsen
        else:
            break  # a real failure does not go away with another radius
    best = _closest(tried, target)
    return best if best is not None else tried[-1]


def cgal_first_radius(previous: list[runs.Run], reference: runs.Run | None, target, longest_side) -> float:
    """The first radius bound to try: from an earlier CGAL run of the surface (V R^2 constant), else
    from the reference mesh's mean edge (CGAL's edges are about 1.3 R long), else from the box."""
    done = [r for r in previous if r.ok and r.vertices]
    if done:
        c = done[-1].vertices * done[-1].value**2
        return math.sqrt(c / target)
    if reference is not None and reference.analysis:
        mean_edge = reference.analysis.get("shape", {}).get("edge_length", {}).get("mean")
        if mean_edge:
            return mean_edge / 1.3 * math.sqrt(reference.vertices / target)
    return longest_side / 64.0
