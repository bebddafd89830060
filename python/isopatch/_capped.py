"""A lattice capped or shelled by planes (docs/lattices.md) meshed as blocks (isopatch.distributed).

One process meshes such a part as the cut surfaces of its parts (the lattice g = 0 cut open by the
polyhedron's planes; a sheet has two walls, a shell its hollows) closed by planar caps. A blocked run
refines every part's cut in blocks on the workers, exactly as any surface (the planes are the cut's
region, so its boundary lands on them in every block to the bit), then the driver puts each part's blocks
together and closes it with its caps, the narrow corners' flips and the last angle repair, as one process
closes its cut. The caps are a few percent of the vertices; the closing holds the whole part in the
driver's memory.
"""

import os
import time
from typing import Any, Callable, Dict, List, Optional, Tuple

import numpy as np

from . import _blocks, _isopatch


def capped_path(job: Dict[str, Any]) -> str:
    """The closed part's file (positions and triangles) in the job's out_dir."""
    return os.path.join(job["out_dir"], "capped-%s.npz" % job["hash"])


def run_capped(client: Any, source: Dict[str, Any], box: Any, opts: Dict[str, Any], tiles: int, out_dir: str,
               output: Optional[str], capped: Dict[str, Any],
               refine_job: Callable[[int], Tuple[Dict[str, Any], List[Dict[str, Any]]]],
               phases: Dict[str, float], start: float) -> Dict[str, Any]:
    """Every cut surface in `tiles` blocks (refine_job(cut) runs one cut's base and blocks; `capped` is
    _isopatch.capped_parts()), then the parts closed by their caps on the driver, written to out_dir (and
    `output`); returns the manifest.

    Raises the library's errors (CreaseError when the caps cannot close a cut, as in one process)."""
    cuts: List[Dict[str, Any]] = []
    meshes: List[Tuple[np.ndarray, np.ndarray]] = []
    summaries_all: List[Dict[str, Any]] = []
    seam_copies = 0
    for cut, part in enumerate(capped["cut_parts"]):
        job, summaries = refine_job(cut)
        plan = job["plan"]
        mark = time.perf_counter()
        seam_copies += _blocks.check_seams(job, plan)
        meshes.append(_blocks.whole_arrays(job))
        phases["merge"] = phases.get("merge", 0.0) + time.perf_counter() - mark
        summaries_all.extend(summaries)
        cuts.append({
            "cut": cut, "part": part, "hash": job["hash"], "level": job["level"],
            "vertices": int(plan["vertices"]), "triangles": int(plan["triangles"]),
            "base": {"file": os.path.basename(_blocks.base_path(job)),
                     "sha256": _blocks.file_digest(_blocks.base_path(job))},
            "block_files": [dict(s, first_vertex=int(plan["first_vertex"][s["block"]]),
                                 first_triangle=int(plan["first_triangle"][s["block"]])) for s in summaries],
        })
    whole = {"source": source, "box": box, "options": opts, "blocks": tiles, "out_dir": os.path.abspath(out_dir)}
    whole["hash"] = _blocks.job_hash(dict(whole, part="capped"))
    mark = time.perf_counter()
    closed = _isopatch.close_capped(source, box, opts, meshes)
    del meshes
    phases["caps"] = time.perf_counter() - mark
    mark = time.perf_counter()
    path = capped_path(whole)
    _blocks._write_npz(path, {"positions": closed["positions"], "triangles": closed["triangles"]})
    manifest: Dict[str, Any] = {
        "format": _blocks.FORMAT,
        "version": _isopatch.__version__,
        "hash": whole["hash"],
        "source": source,
        "box": box,
        "options": opts,
        "blocks": tiles,
        "vertices": int(closed["positions"].shape[0]),
        "triangles": int(closed["triangles"].shape[0]),
        "parts": capped["parts"],
        "cuts": cuts,
        "capped": {"file": os.path.basename(path), "sha256": _blocks.file_digest(path), "caps": closed["caps"],
                   "crease_vertices": closed["crease_vertices"], "repair_moves": closed["repair_moves"]},
        "seam_copies_checked": seam_copies,
        "computed": sum(1 for s in summaries_all if not s["reused"]),
        "reused": sum(1 for s in summaries_all if s["reused"]),
        "seam_band_vertices": sum(s["seam_band_vertices"] for s in summaries_all),
    }
    if output:
        _isopatch.write_arrays(closed["positions"], closed["triangles"], output)
        manifest["output"] = {"file": os.path.abspath(output), "sha256": _blocks.file_digest(output)}
    phases["merge"] = phases.get("merge", 0.0) + time.perf_counter() - mark
    manifest["seconds"] = time.perf_counter() - start
    manifest["phase_seconds"] = phases
    return _blocks.write_manifest_file(whole, manifest)

