"""Meshing one surface as blocks on a Dask cluster (docs/distributed.md).

The driver makes the coarse base once (the multiresolution base of one process), cuts its triangles
into blocks along a space-filling curve and asks Dask to refine every block on a worker. A point on a
base edge between two blocks is made from that edge alone and held, so both blocks make it to the bit;
the numbers of the output's vertices are fixed before any block runs, so the merged mesh is the same
bytes with any number of workers and any order of tasks. Every task writes its file under a temporary
name and renames it; a task run twice, or a driver run again with the same settings, reuses what is
there.

Command line: ``python3 -m isopatch.distributed SURFACE --tiles N --out-dir DIR [-o FILE] ...`` (the
``isopatch mesh ... --tiles N`` command runs it).
"""

import argparse
import os
import sys
import time
from typing import Any, Callable, Dict, List, Literal, Optional, Sequence, Tuple, Union

from . import _blocks, _capped, _isopatch, _prefilter, _tiles
from ._api import BoxLike, _box
from ._errors import (CreaseError, Error, EvaluationError, InputError, IoError, LimitError, NoSurfaceError,
                      ParseError, SingularSurfaceError, UnknownSurfaceError)

#: How long the driver waits for the workers of a cluster to start.
WORKER_START_SECONDS = 120

#: Settings a blocked run passes to the library (the keyword arguments of isopatch.mesh that apply).
_OPTIONS = ("edge_length", "quality", "refine", "remesh", "resolution", "max_evaluations", "time_limit",
            "creases")


def _job(source: Dict[str, Any], box: Any, options: Dict[str, Any], tiles: int, out_dir: str,
         split: str = "blocks", part: Optional[int] = None) -> Dict[str, Any]:
    if not isinstance(tiles, int) or tiles < 1:
        raise InputError("tiles must be a whole number of at least 1", "tiles")
    os.makedirs(out_dir, exist_ok=True)
    job = {"source": source, "box": box, "options": options, "blocks": tiles, "out_dir": os.path.abspath(out_dir)}
    if split != "blocks":
        job["split"] = split
    if part is not None:
        job["part"] = part
    job["hash"] = _blocks.job_hash(job)
    return job


def _start_client(scheduler: Any, workers: int, memory_limit: Union[str, int, None]):
    """A Dask client: the one given, one connected to tcp://HOST:PORT, or a LocalCluster of `workers`
    processes of one thread each on 127.0.0.1 without a dashboard ("local"). Returns (client, cluster)."""
    try:
        from distributed import Client, LocalCluster
    except ImportError as e:  # pragma: no cover - the set-up script installs it
        raise InputError("isopatch.distributed needs Dask distributed (apt-get install python3-distributed)") from e
    if not isinstance(scheduler, str):
        return scheduler, None
    if scheduler == "local":
        if not isinstance(workers, int) or workers < 1:
            raise InputError("workers must be a whole number of at least 1", "workers")
        # No dashboard; the scheduler's small HTTP server (health, metrics) on a free loopback port. Dask
        # starts workers with glibc's trim threshold at 64 KiB, which made the refinement's allocations
        # 1.5-2 times slower (docs/distributed.md); the workers isopatch starts keep glibc's own.
        import dask
        environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}) or {})
        environ.pop("MALLOC_TRIM_THRESHOLD_", None)
        with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}):
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                                   dashboard_address="127.0.0.1:0", scheduler_kwargs={"dashboard": False},
                                   memory_limit=memory_limit if memory_limit else "auto")
        client = Client(cluster)
        _wait_for_workers(client, workers, cluster)
        return client, cluster
    if scheduler.startswith("tcp://") or scheduler.startswith("tls://"):
        client = Client(scheduler, timeout=30)
        _wait_for_workers(client, 1, None)
        return client, None
    raise InputError("the scheduler must be 'local' or tcp://HOST:PORT, not %r" % scheduler, "scheduler")


def _wait_for_workers(client: Any, count: int, cluster: Any) -> None:
    """Waits (at most WORKER_START_SECONDS) until `count` workers are there, instead of waiting forever
    for tasks no worker runs."""
    try:
        client.wait_for_workers(count, timeout=WORKER_START_SECONDS)
    except Exception:  # distributed raises TimeoutError of several modules
        client.close()
        if cluster is not None:
            cluster.close()
        raise Error("the Dask cluster has fewer than %d worker%s after %d s (a script that starts a local "
                    "cluster must run its main code under if __name__ == '__main__')"
                    % (count, "s" if count > 1 else "", WORKER_START_SECONDS)) from None


def _run_blocks(client: Any, job: Dict[str, Any]) -> List[Dict[str, Any]]:
    """Every block's task on the cluster (Dask retries a task whose worker was lost); the summaries in
    block order. The tests submit them in reverse order too (job["reverse"])."""
    order = list(range(job["blocks"]))
    if job.get("reverse"):
        order.reverse()
    futures = client.map(_blocks.run_block, [job] * len(order), order, pure=False)
    return sorted(client.gather(futures), key=lambda s: s["block"])


def mesh_blocks(
    surface: Optional[str] = None,
    *,
    tiles: int,
    out_dir: str,
    box: Optional[BoxLike] = None,
    params: Optional[Dict[str, float]] = None,
    volume: Optional[str] = None,
    level: float = 0.0,
    prefilter_window: int = _prefilter.DEFAULT_WINDOW,
    output: Optional[str] = None,
    scheduler: Any = "local",
    workers: int = 2,
    memory_limit: Union[str, int, None] = None,
    split: Literal["blocks", "planes"] = "blocks",
    _test: Optional[Dict[str, Any]] = None,
    **options: Any,
) -> Dict[str, Any]:
    """Meshes `surface` (a formula, catalogue name, ``@file`` or a composite's ``.ipatch`` file; or
    ``volume=`` a .npy/.nrrd file at ``level``) as `tiles` blocks refined on Dask workers, writing per-block files and a manifest into
    `out_dir` and, with `output`, the whole mesh (a .ply streamed block by block; any other format
    isopatch writes, e.g. .3mf, through one mesh in memory).

    A volume's B-spline coefficients are made first by a distributed pass over windows of
    `prefilter_window` samples per side, each read with a halo of 32 (equal to the whole volume's
    coefficients to rounding), into one .npy file in `out_dir` that every task maps instead of reading
    the volume; a .npy volume is read by the workers window by window.

    split: "blocks" (one base made by the driver, its triangles cut into `tiles` blocks) or "planes"
    (for bases too large for one machine: the box cut by planes into at least `tiles` tiles, the curves
    of every face of the lattice traced first by one task each, then every tile's base and refinement
    made by one task on its faces' curves; formulas, catalogue surfaces and volumes, not composites or
    formulas with exact creases).

    scheduler: "local" (a LocalCluster of `workers` processes with one thread each on 127.0.0.1, with
    `memory_limit` per worker), "tcp://HOST:PORT" (a running scheduler) or a distributed.Client.
    options: edge_length, quality, refine, remesh, resolution, max_evaluations, time_limit, creases.

    Returns the manifest (a dict; also in out_dir/manifest-HASH.json) with "manifest" (its path),
    "computed" and "reused" block counts and "seconds".

    Raises the library's errors (InputError, SettingError, LimitError "use more blocks" when a block is
    larger than its worker's memory limit, ...), from the driver or from the worker that met them.
    """
    if split not in ("blocks", "planes"):
        raise InputError("split must be 'blocks' or 'planes', not %r" % (split,), "split")
    unknown = sorted(set(options) - set(_OPTIONS))
    if unknown:
        raise InputError("unknown setting %r for a blocked run" % unknown[0], unknown[0])
    if (surface is None) == (volume is None):
        raise InputError("give a surface or a volume, not both or neither", "surface")
    source: Dict[str, Any] = {"spec": _spec_source(surface), "params": dict(params or {})}
    if volume is not None:
        source = _volume_source(volume, level, prefilter_window)
    opts = {k: v for k, v in options.items() if v is not None}
    start = time.perf_counter()
    client, cluster = _start_client(scheduler, workers, memory_limit)
    phases = {"cluster": time.perf_counter() - start, "base": 0.0, "blocks": 0.0}
    try:
        prefiltered: Optional[Dict[str, Any]] = None
        if volume is not None:
            os.makedirs(out_dir, exist_ok=True)
            prefiltered = _prefilter.coefficients(client, source["volume"], source["volume_sha256"],
                                                  source["level"], prefilter_window, os.path.abspath(out_dir))
            source.update(coefficients=prefiltered["coefficients"], spacing=prefiltered["spacing"],
                          origin=prefiltered["origin"])
            phases["prefilter"] = prefiltered["seconds"]
        if split == "planes":
            return _run_planes(client, source, _box(box), opts, tiles, out_dir, output, _test, phases, start,
                               _prefilter_extra(prefiltered))
        if volume is None and split == "blocks":
            capped = _isopatch.capped_parts(source, _box(box), opts)
            if capped is not None:
                return _capped.run_capped(client, source, _box(box), opts, tiles, out_dir, output, capped,
                                          lambda cut: _refine_job(client, source, _box(box), opts, tiles, out_dir,
                                                                  _test, phases, cut), phases, start)
        job, summaries = _refine_job(client, source, _box(box), opts, tiles, out_dir, _test, phases)
        plan = job["plan"]
        mark = time.perf_counter()
        extra: Dict[str, Any] = {"seam_copies_checked": _blocks.check_seams(job, plan)}
        extra.update(_prefilter_extra(prefiltered))
        if output:
            path: str = output
            extra["output"] = _write_output(path, lambda: _blocks.write_ply(job, plan, path),
                                            lambda: _blocks.write_other(job, plan, path))
        extra["computed"] = sum(1 for s in summaries if not s["reused"])
        extra["reused"] = sum(1 for s in summaries if s["reused"])
        phases["merge"] = time.perf_counter() - mark
        extra["seconds"] = time.perf_counter() - start
        extra["phase_seconds"] = phases
        extra["seam_band_vertices"] = sum(s["seam_band_vertices"] for s in summaries)
        return _blocks.write_manifest(job, plan, summaries, extra)
    finally:
        if cluster is not None:
            client.close()
            cluster.close()


def _refine_job(client: Any, source: Dict[str, Any], box: Any, opts: Dict[str, Any], tiles: int, out_dir: str,
                test: Optional[Dict[str, Any]], phases: Dict[str, float],
                part: Optional[int] = None) -> Tuple[Dict[str, Any], List[Dict[str, Any]]]:
    """One surface's base and blocks (cut surface `part` of a capped lattice): the job and its
    blocks' summaries. A refinement that fails its guard is made again at half the level, as one
    process does."""
    opts = dict(opts)
    while True:
        job = _job(source, box, opts, tiles, out_dir, part=part)
        job.update(test or {})
        mark = time.perf_counter()
        job["level"] = _blocks.make_base(job)
        job["plan"] = _blocks.job_state(job).counts()
        phases["base"] += time.perf_counter() - mark
        mark = time.perf_counter()
        summaries = _run_blocks(client, job)
        phases["blocks"] += time.perf_counter() - mark
        if _all_kept(summaries, job["level"], "block", "mesh it in one process, whose level-1 mesher has "
                                                         "the clean-up a block lacks"):
            return job, summaries
        opts["refine"] = job["level"] // 2


def _write_output(output: str, ply: Callable[[], None], other: Callable[[], None]) -> Dict[str, Any]:
    """Writes the whole mesh (a .ply streamed by `ply`, another format by `other`); the manifest's entry."""
    (ply if output.lower().endswith(".ply") else other)()
    return {"file": os.path.abspath(output), "sha256": _blocks.file_digest(output)}


def _all_kept(summaries: Sequence[Dict[str, Any]], level: int, what: str, advice: str) -> bool:
    """Whether every block's or tile's refinement is kept; raises LimitError (with `advice`) when one is
    not at level 1, where halving the level is no way out."""
    failed = [s for s in summaries if not s["kept"]]
    if failed and level <= 1:
        worst = failed[0]
        raise LimitError("%s %d of this surface fails the refinement's guard even at level 1 (smallest angle "
                         "%.1f degrees, %d points not landed): %s"
                         % (what, worst["block"], worst["smallest_angle"], worst["failed_points"], advice))
    return not failed


def _prefilter_extra(prefiltered: Optional[Dict[str, Any]]) -> Dict[str, Any]:
    """The manifest's record of a volume's distributed prefilter (nothing without one)."""
    if prefiltered is None:
        return {}
    return {"prefilter": {"file": os.path.basename(prefiltered["coefficients"]),
                          "windows": prefiltered["windows"], "window": prefiltered["window"],
                          "halo": prefiltered["halo"], "reused": prefiltered["reused"],
                          "worker_peak_rss_bytes": prefiltered.get("worker_peak_rss_bytes", 0),
                          "sample_range": [prefiltered["min"], prefiltered["max"]]}}


def _run_planes(client: Any, source: Dict[str, Any], box: Any, opts: Dict[str, Any], tiles: int, out_dir: str,
                output: Optional[str], test: Optional[Dict[str, Any]], phases: Dict[str, float], start: float,
                extra: Dict[str, Any]) -> Dict[str, Any]:
    """A run in tiles by planes (split="planes"): the plan, the faces' tasks, the tiles' tasks, the merge.
    A tile whose refinement is not kept halves the level for every tile, as one process does."""
    phases["faces"] = 0.0
    while True:
        job = _job(source, box, opts, tiles, out_dir, "planes")
        job.update(test or {})
        mark = time.perf_counter()
        job["plan"] = _tiles.make_plan(job)
        job["level"] = job["plan"]["level"]
        counts = job["plan"]["counts"]
        job["tile_count"] = counts[0] * counts[1] * counts[2]
        phases["base"] += time.perf_counter() - mark
        mark = time.perf_counter()
        faces = list(range(_tiles.face_count(counts)))
        face_summaries = client.gather(client.map(_tiles.run_face, [job] * len(faces), faces, pure=False))
        phases["faces"] += time.perf_counter() - mark
        mark = time.perf_counter()
        order = list(range(job["tile_count"]))
        if job.get("reverse"):
            order.reverse()
        summaries = sorted(client.gather(client.map(_tiles.run_tile, [job] * len(order), order, pure=False)),
                           key=lambda s: s["tile"])
        phases["blocks"] += time.perf_counter() - mark
        if _all_kept(summaries, job["level"], "tile", "use other tile counts, or blocks of one base"):
            break
        opts["refine"] = job["level"] // 2
    mark = time.perf_counter()
    numbering = _tiles.number_tiles(job)
    if output:
        path: str = output
        extra["output"] = _write_output(path, lambda: _tiles.write_ply(job, numbering, path),
                                        lambda: _tiles.write_other(job, numbering, path))
    phases["merge"] = time.perf_counter() - mark
    plan = {"vertices": numbering["vertices"], "triangles": numbering["triangles"],
            "first_vertex": [0] * job["tile_count"], "first_triangle": [0] * job["tile_count"]}
    first_vertex = first_triangle = 0
    for t, s in enumerate(summaries):
        plan["first_vertex"][t] = first_vertex
        plan["first_triangle"][t] = first_triangle
        first_vertex += int(numbering["owned"][t].sum())
        first_triangle += s["triangles"]
    extra.update({
        "split": "planes",
        "tile_counts": counts,
        "planes": [[float(x) for x in p] for p in job["plan"]["planes"]],
        "edge": job["plan"]["edge"],
        "face_files": [dict(f, file=os.path.basename(_tiles.face_path(job, f["face"]))) for f in face_summaries],
        "plan_file": {"file": os.path.basename(_tiles.plan_path(job)),
                      "sha256": _blocks.file_digest(_tiles.plan_path(job))},
        "seam_vertices": numbering["seam_vertices"],
        "computed": sum(1 for s in summaries if not s["reused"]),
        "reused": sum(1 for s in summaries if s["reused"]),
        "seconds": time.perf_counter() - start,
        "phase_seconds": phases,
        "seam_band_vertices": sum(s["seam_band_vertices"] for s in summaries),
    })
    job["blocks"] = job["tile_count"]
    return _blocks.write_manifest(job, plan, summaries, extra, base=None)


def _spec_source(surface: Optional[str]) -> Optional[str]:
    """A surface spec as the workers read it: a file it names (``@file``, a ``.ipatch`` composite) made
    absolute. Raises IoError for a named file that is not there."""
    if not isinstance(surface, str):
        return surface
    named = surface[1:] if surface.startswith("@") else surface if surface.endswith(".ipatch") else None
    if named is None:
        return surface
    if not os.path.isfile(named):
        raise IoError("%s: cannot open: no such file" % named)
    path = os.path.abspath(named)
    return "@" + path if surface.startswith("@") else path


def _volume_source(volume: str, level: float, window: int) -> Dict[str, Any]:
    """The source of a volume file, with the SHA-256 of its bytes. Raises IoError for a file that is
    not there or not a .npy or .nrrd, InputError for a non-finite level or a bad window."""
    path = os.path.abspath(volume)
    if not path.lower().endswith((".npy", ".nrrd")):
        raise IoError("%s: not a volume file (want .npy or .nrrd)" % volume)
    if not os.path.isfile(path):
        raise IoError("%s: cannot open: no such file" % volume)
    if not isinstance(level, (int, float)) or level != level or abs(level) == float("inf"):
        raise InputError("the level must be finite", "level")
    _prefilter.plan_windows((2, 2, 2), window)  # checks the window
    return {"volume": path, "level": float(level), "volume_sha256": _blocks.file_digest(path),
            "prefilter_window": window}


def _triple(text: str, name: str) -> Tuple[float, ...]:
    try:
        values = tuple(float(v) for v in text.split(","))
    except ValueError:
        raise InputError("%s must be numbers separated by commas" % name, name) from None
    return values


#: Exit codes as the command-line tool's (apps/isopatch/error_report.hpp); 2 is a usage error.
_EXIT_CODES = ((UnknownSurfaceError, 4), (ParseError, 5), (IoError, 6), (EvaluationError, 7), (NoSurfaceError, 8),
               (LimitError, 9), (SingularSurfaceError, 10), (CreaseError, 11), (InputError, 3))


def _exit_code(error: Error) -> int:
    for kind, code in _EXIT_CODES:
        if isinstance(error, kind):
            return code
    return 1


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command line; exit codes as `isopatch mesh`'s (3 bad input, 9 a limit, ...)."""
    p = argparse.ArgumentParser(prog="isopatch mesh --tiles", description=__doc__.split("\n\n")[0])
    p.add_argument("surface", help="formula, catalogue name, @file, or a .npy/.nrrd volume")
    p.add_argument("--tiles", type=int, required=True, help="number of blocks")
    p.add_argument("--out-dir", required=True, help="directory of the block files and the manifest")
    p.add_argument("-o", "--output", help="also write the whole mesh here (.ply streamed; .3mf, .stl, ...)")
    p.add_argument("--scheduler", default="local", help="'local' or tcp://HOST:PORT")
    p.add_argument("--workers", type=int, default=2, help="worker processes of a local cluster")
    p.add_argument("--memory-limit", default=None, help="per local worker, e.g. 2GB")
    p.add_argument("--box", help="xmin,ymin,zmin,xmax,ymax,zmax")
    p.add_argument("--param", action="append", default=[], help="NAME=VALUE")
    p.add_argument("--level", type=float, default=0.0, help="level of a volume")
    p.add_argument("--prefilter-window", type=int, default=_prefilter.DEFAULT_WINDOW,
                   help="samples per side of a volume's prefilter windows")
    p.add_argument("--edge-length", type=float)
    p.add_argument("--quality")
    p.add_argument("--refine", type=int)
    p.add_argument("--creases")
    p.add_argument("--split", default="blocks", choices=("blocks", "planes"),
                   help="blocks of one base (default) or tiles of the box by planes")
    a = p.parse_args(argv)
    try:
        box = None
        if a.box:
            v = _triple(a.box, "box")
            if len(v) != 6:
                raise InputError("box must be six numbers", "box")
            box = (v[:3], v[3:])
        params = {}
        for item in a.param:
            name, _, value = item.partition("=")
            try:
                params[name] = float(value)
            except ValueError:
                raise InputError("--param wants NAME=VALUE, not %r" % item, "param") from None
        is_volume = a.surface.lower().endswith((".npy", ".nrrd"))
        manifest = mesh_blocks(None if is_volume else a.surface, volume=a.surface if is_volume else None,
                               level=a.level, prefilter_window=a.prefilter_window, tiles=a.tiles,
                               out_dir=a.out_dir, box=box, params=params,
                               output=a.output, scheduler=a.scheduler, workers=a.workers,
                               memory_limit=a.memory_limit, edge_length=a.edge_length, quality=a.quality,
                               refine=a.refine, creases=a.creases, split=a.split)
    except Error as e:
        print("isopatch: error: %s" % e.command_line_message, file=sys.stderr)
        return _exit_code(e)
    print("isopatch: %d vertices, %d triangles in %d %s (%d made, %d reused) in %.1f s; manifest %s%s"
          % (manifest["vertices"], manifest["triangles"], manifest["blocks"],
             "tiles" if manifest.get("split") == "planes" else "blocks", manifest["computed"],
             manifest["reused"], manifest["seconds"], manifest["manifest"],
             "; mesh " + manifest["output"]["file"] if "output" in manifest else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
