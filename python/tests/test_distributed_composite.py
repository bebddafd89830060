"""Composite surfaces (.ipatch: I-patches, setback vertex blends) and formulas with exact creases (CSG
shapes) meshed as blocks on Dask (isopatch.distributed): watertight across blocks and along the curves,
every vertex on its patch, the topology, vertex count and nearly the quality of one process, the same
bytes with one worker and tasks in reverse order, reused when run again; the command line takes a
.ipatch with --tiles and writes a 3MF that prusa-slicer reads as one manifold part."""

import json
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

from conftest import expect_one_manifold_part, read_ply, require
import isopatch
from isopatch import IoError, distributed

require("distributed", "python3-distributed")

CLI = os.environ.get("ISOPATCH_CLI")
EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples")
BLEND = os.path.join(EXAMPLES, "rounded_box.ipatch")
EDGE = 0.04
TILES = 6


def analyze(path, surface):
    """The tool's report of a mesh file against a composite (its accuracy on the patches' functions)."""
    run = subprocess.run([CLI, "analyze", str(path), "--surface", surface, "--json"], capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    return json.loads(run.stdout)


@pytest.fixture(scope="module")
def blend_run(client, tmp_path_factory):
    out = tmp_path_factory.mktemp("composite")
    manifest = distributed.mesh_blocks(BLEND, edge_length=EDGE, tiles=TILES, out_dir=str(out),
                                       output=str(out / "blend.ply"), scheduler=client)
    return out, manifest


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_a_blend_in_blocks_is_watertight_on_its_patches_and_as_good_as_one_process(blend_run, tmp_path):
    out, manifest = blend_run
    assert manifest["blocks"] == TILES and manifest["computed"] + manifest["reused"] == TILES
    assert manifest["level"] >= 2 and manifest["seam_copies_checked"] > 0
    vertices, faces = read_ply(out / "blend.ply")
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    keys = directed[:, 0] * len(vertices) + directed[:, 1]
    assert len(np.unique(keys)) == len(keys), "an edge is traversed twice the same way"
    assert np.isin(directed[:, 1] * len(vertices) + directed[:, 0], keys).all(), "a crack between blocks"
    assert len(np.unique(vertices, axis=0)) == len(vertices), "two vertices at one position"
    one_path = tmp_path / "one.ply"
    run = subprocess.run([CLI, "mesh", BLEND, "--edge-length", str(EDGE), "-o", str(one_path)],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    blocked, one = analyze(out / "blend.ply", BLEND), analyze(one_path, BLEND)
    assert blocked["topology"]["vertices"] == one["topology"]["vertices"]  # the same level and base as one process
    for key in ("euler_characteristic", "components", "watertight", "outward_oriented"):
        assert blocked["topology"][key] == one["topology"][key], key
    assert blocked["self_intersections"]["pairs"] == 0
    assert blocked["accuracy"]["vertex_distance"]["max"] < 1e-9
    assert blocked["valence"]["share_6"] > one["valence"]["share_6"] - 0.02
    # The cuts run along curves where they can, whose points one process holds too (docs/distributed.md).
    assert blocked["shape"]["min_angle_degrees"]["min"] > min(24.0, one["shape"]["min_angle_degrees"]["min"] - 1)


def test_one_worker_and_tasks_in_reverse_order_give_the_same_bytes_and_a_rerun_reuses(blend_run, tmp_path):
    out, first = blend_run
    manifest = distributed.mesh_blocks(BLEND, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                       output=str(tmp_path / "one.ply"), workers=1, _test={"reverse": True})
    assert manifest["hash"] == first["hash"] and manifest["computed"] >= 1
    assert (tmp_path / "one.ply").read_bytes() == (out / "blend.ply").read_bytes()
    again = distributed.mesh_blocks(BLEND, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                    output=str(tmp_path / "again.ply"), workers=1)
    assert again["reused"] == TILES and again["computed"] == 0
    assert (tmp_path / "again.ply").read_bytes() == (out / "blend.ply").read_bytes()


def test_an_edited_composite_is_another_job(client, blend_run, tmp_path):
    out, first = blend_run
    copy = tmp_path / "blend.ipatch"
    shutil.copy(BLEND, copy)
    same = distributed.mesh_blocks(str(copy), edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                   scheduler=client)
    assert same["vertices"] == first["vertices"]
    with open(copy, "a") as f:
        f.write("\n# edited\n")
    edited = distributed.mesh_blocks(str(copy), edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                     scheduler=client)
    assert edited["hash"] != same["hash"] and edited["reused"] == 0


def test_a_missing_composite_is_refused_in_one_line(client, tmp_path):
    with pytest.raises(IoError, match="no such file"):
        distributed.mesh_blocks(str(tmp_path / "absent.ipatch"), tiles=2, out_dir=str(tmp_path), scheduler=client)


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_the_command_line_writes_a_composites_3mf_the_slicer_takes_as_one_manifold_part(tmp_path):
    cube = os.path.join(EXAMPLES, "cube.ipatch")
    part, ply = tmp_path / "cube.3mf", tmp_path / "cube.ply"
    for path in (part, ply):
        run = subprocess.run([CLI, "mesh", cube, "--edge-length", "0.08", "--tiles", "4", "--out-dir",
                              str(tmp_path / "blocks"), "-o", str(path), "--workers", "2"], capture_output=True,
                             text=True, timeout=600)
        assert run.returncode == 0, run.stderr[-2000:]
        assert re.search(r"manifest (\S+?);", run.stdout)
    vertices, faces = read_ply(ply)
    expect_one_manifold_part(part, vertices, faces)


# A cube with a round hole through it: 14 creases, 8 corners, genus 1. Written as the complement of a
# union so that one process meshes it on the general crease path, as blocks do (max(box, hole), a smooth
# solid capped by planes, is meshed in one process as its cut surface closed by caps: docs/lattices.md).
HOLED_CUBE = "-min(1-max(max(abs(x),abs(y)),abs(z)), sqrt(x^2+y^2)-0.5)"
CUBE_BOX = ((-1.5, -1.5, -1.5), (1.5, 1.5, 1.5))


def test_a_formula_with_creases_in_blocks_keeps_its_creases_and_corners(client, tmp_path):
    # The automatic level keeps level 1 on such shapes (docs/distributed.md); level 2 is asked for.
    manifest = distributed.mesh_blocks(HOLED_CUBE, box=CUBE_BOX, edge_length=0.06, refine=2, tiles=4,
                                       out_dir=str(tmp_path), output=str(tmp_path / "holed.ply"), scheduler=client)
    assert manifest["level"] == 2 and manifest["seam_copies_checked"] > 0
    vertices, faces = read_ply(tmp_path / "holed.ply")
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    keys = directed[:, 0] * len(vertices) + directed[:, 1]
    assert len(np.unique(keys)) == len(keys)
    assert np.isin(directed[:, 1] * len(vertices) + directed[:, 0], keys).all(), "a crack between blocks"
    assert len(np.unique(vertices, axis=0)) == len(vertices)
    box = np.max(np.abs(vertices), axis=1) - 1.0
    hole = 0.5 - np.hypot(vertices[:, 0], vertices[:, 1])
    assert np.max(np.abs(np.maximum(box, hole))) < 1e-9  # on the shape
    for corner in np.array(np.meshgrid([-1, 1], [-1, 1], [-1, 1])).T.reshape(-1, 3):
        assert np.min(np.linalg.norm(vertices - corner, axis=1)) < 1e-12
    second = np.sort(np.abs(vertices), axis=1)[:, 1]
    near_edge = second > 1 - 1e-3
    assert near_edge.sum() > 100
    np.testing.assert_allclose(second[near_edge], 1.0, atol=1e-12)  # the cube's edges held exactly
    blocked = isopatch.Mesh.from_arrays(vertices, faces, HOLED_CUBE, box=CUBE_BOX).analyze()
    one = isopatch.mesh(HOLED_CUBE, box=CUBE_BOX, edge_length=0.06, refine=2).analyze()
    assert blocked["topology"]["vertices"] == one["topology"]["vertices"]
    assert blocked["topology"]["euler_characteristic"] == one["topology"]["euler_characteristic"] == 0
    assert blocked["topology"]["watertight"] and blocked["topology"]["outward_oriented"]
    assert blocked["valence"]["share_6"] > one["valence"]["share_6"] - 0.02
    assert blocked["shape"]["min_angle_degrees"]["min"] > min(24.0, one["shape"]["min_angle_degrees"]["min"] - 1)
