"""Tiles of the box by planes on Dask (isopatch.distributed, split="planes"): every face's curves traced
once by a task of its own, every tile's base and refinement made by another on those curves; the
gyroid lattice in 8 tiles is watertight across the planes, on f = 0, of one process's topology and
nearly its quality off the seams (the band along the planes reported apart), the same bytes with one
worker and tasks in reverse order, survives a worker killed in the middle, reuses finished tiles when
run again; the command line writes a 3MF of a torus cut by planes that prusa-slicer reads as one
manifold part."""

import json
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

import isopatch
from conftest import expect_one_manifold_part, read_ply, require
from isopatch import distributed
from isopatch._tiles import seam_band_angles

require("distributed", "python3-distributed")

CLI = os.environ.get("ISOPATCH_CLI")
GYROID = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)"
BOX = ((-3.0, -3.0, -3.0), (3.0, 3.0, 3.0))
EDGE = 0.06
TILES = 8


def analyze(path, surface, box=None):
    run = subprocess.run([CLI, "analyze", str(path), "--surface", surface, "--json"]
                         + (["--box", box] if box else []), capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    return json.loads(run.stdout)


@pytest.fixture(scope="module")
def planes_run(client, tmp_path_factory):
    out = tmp_path_factory.mktemp("planes")
    manifest = distributed.mesh_blocks(GYROID, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(out),
                                       output=str(out / "gyroid.ply"), scheduler=client, split="planes")
    return out, manifest


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_a_gyroid_in_tiles_by_planes_is_watertight_on_f_and_near_one_process(planes_run, tmp_path):
    out, manifest = planes_run
    assert manifest["split"] == "planes" and manifest["blocks"] == TILES
    assert manifest["tile_counts"] == [2, 2, 2] and manifest["seam_vertices"] > 0
    assert len(manifest["face_files"]) == 36 and manifest["base"] is None
    vertices, faces = read_ply(out / "gyroid.ply")
    assert len(vertices) == manifest["vertices"] > 30000
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    keys = directed[:, 0] * len(vertices) + directed[:, 1]
    assert len(np.unique(keys)) == len(keys), "an edge is traversed twice the same way"
    # Every edge without its reverse lies on the box's faces: none on a plane between tiles.
    alone = ~np.isin(directed[:, 1] * len(vertices) + directed[:, 0], keys)
    ends = vertices[directed[alone]].reshape(-1, 3)
    on_box = (ends == np.array(BOX[0])).any(axis=1) | (ends == np.array(BOX[1])).any(axis=1)
    assert on_box.all(), "a crack between tiles"
    assert len(np.unique(vertices, axis=0)) == len(vertices), "two vertices at one position"
    box = "%g,%g,%g,%g,%g,%g" % (BOX[0] + BOX[1])
    one_path = tmp_path / "one.ply"
    run = subprocess.run([CLI, "mesh", GYROID, "--box", box, "--edge-length", str(EDGE), "-o", str(one_path)],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    tiled, one = analyze(out / "gyroid.ply", GYROID, box), analyze(one_path, GYROID, box)
    assert tiled["topology"]["non_manifold_edges"] == 0 and tiled["topology"]["consistently_oriented"]
    assert tiled["topology"]["euler_characteristic"] == one["topology"]["euler_characteristic"]
    assert tiled["topology"]["components"] == one["topology"]["components"]
    assert tiled["self_intersections"]["pairs"] == 0
    assert tiled["accuracy"]["vertex_distance"]["max"] < 1e-9
    assert tiled["valence"]["share_6"] > one["valence"]["share_6"] - 0.02
    band, rest, _ = seam_band_angles(vertices, faces, manifest["planes"], EDGE * manifest["level"])
    assert rest > 20.0, (band, rest)
    assert band > 10.0, (band, rest)
    assert manifest["seam_band_vertices"] > 0


def test_one_worker_and_tasks_in_reverse_order_give_the_same_bytes(planes_run, tmp_path):
    out, _ = planes_run
    manifest = distributed.mesh_blocks(GYROID, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                       output=str(tmp_path / "one.ply"), workers=1, split="planes",
                                       _test={"reverse": True})
    assert manifest["computed"] == TILES
    assert (tmp_path / "one.ply").read_bytes() == (out / "gyroid.ply").read_bytes()


def test_a_worker_killed_in_the_middle_leaves_the_same_bytes(client, planes_run, tmp_path):
    out, _ = planes_run
    marker = tmp_path / "killed"
    manifest = distributed.mesh_blocks(GYROID, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                       output=str(tmp_path / "after_kill.ply"), scheduler=client, split="planes",
                                       _test={"kill_marker": str(marker), "kill_block": 5})
    assert marker.exists(), "the task did not kill its worker"
    assert manifest["computed"] + manifest["reused"] == TILES
    assert (tmp_path / "after_kill.ply").read_bytes() == (out / "gyroid.ply").read_bytes()


def test_a_driver_run_again_reuses_finished_tiles_and_faces(client, planes_run, tmp_path):
    out, first = planes_run
    for name in os.listdir(out):
        if name.startswith(("plan-", "face-", "tile-")):
            shutil.copy(out / name, tmp_path / name)
    os.remove(tmp_path / first["block_files"][2]["file"])  # as if the driver stopped before tile 2
    again = distributed.mesh_blocks(GYROID, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                    output=str(tmp_path / "again.ply"), scheduler=client, split="planes")
    assert {b["block"] for b in again["block_files"] if not b["reused"]} == {2}
    assert all(f["reused"] for f in again["face_files"])
    assert (tmp_path / "again.ply").read_bytes() == (out / "gyroid.ply").read_bytes()
    # Blocks of one base are another job than tiles by planes: nothing of theirs is read.
    assert again["hash"] == first["hash"]
    blocks = distributed.mesh_blocks(GYROID, box=BOX, edge_length=0.3, tiles=TILES, out_dir=str(tmp_path),
                                     scheduler=client)
    assert blocks["hash"] != first["hash"] and "split" not in blocks


def test_tiles_from_another_run_are_refused(client, planes_run, tmp_path):
    out, first = planes_run
    for name in os.listdir(out):
        if name.startswith(("plan-", "face-", "tile-")):
            shutil.copy(out / name, tmp_path / name)
    # A tile of the sphere in place of the gyroid's tile 3: its seams match nothing across.
    other = distributed.mesh_blocks("x^2+y^2+z^2-4", box=BOX, edge_length=EDGE, tiles=TILES,
                                    out_dir=str(tmp_path / "sphere"), scheduler=client, split="planes")
    shutil.copy(tmp_path / "sphere" / other["block_files"][3]["file"], tmp_path / first["block_files"][3]["file"])
    with pytest.raises(isopatch.InputError, match="no copy across"):
        distributed.mesh_blocks(GYROID, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                scheduler=client, split="planes")


def test_a_sampled_volume_in_tiles_by_planes_is_a_closed_torus(client, tmp_path):
    axis = np.linspace(-1.0, 1.0, 64)
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    np.save(tmp_path / "torus.npy", np.sqrt((np.hypot(x, y) - 0.6) ** 2 + z ** 2) - 0.25)
    manifest = distributed.mesh_blocks(volume=str(tmp_path / "torus.npy"), level=0.0, tiles=8,
                                       out_dir=str(tmp_path / "out"), output=str(tmp_path / "torus.ply"),
                                       scheduler=client, split="planes")
    assert manifest["split"] == "planes" and manifest["tile_counts"] == [2, 2, 2] and "prefilter" in manifest
    vertices, faces = read_ply(tmp_path / "torus.ply")
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    keys = directed[:, 0] * len(vertices) + directed[:, 1]
    assert len(np.unique(keys)) == len(keys)
    assert np.isin(directed[:, 1] * len(vertices) + directed[:, 0], keys).all(), "not closed"
    euler = len(vertices) - len(keys) // 2 + len(faces)
    assert euler == 0


def test_what_tiles_by_planes_do_not_take_is_refused(client, tmp_path):
    blend = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "rounded_box.ipatch")
    with pytest.raises(isopatch.SettingError, match="blocks of its base"):
        distributed.mesh_blocks(blend, tiles=2, out_dir=str(tmp_path), scheduler=client, split="planes")
    with pytest.raises(isopatch.SettingError, match="creases"):
        distributed.mesh_blocks("max(x^2+y^2+z^2-1, -(x^2+y^2-0.25))", box=((-1.2,) * 3, (1.2,) * 3), tiles=2,
                                out_dir=str(tmp_path), scheduler=client, split="planes")
    with pytest.raises(isopatch.InputError, match="split"):
        distributed.mesh_blocks(GYROID, box=BOX, tiles=2, out_dir=str(tmp_path), scheduler=client, split="cubes")
    with pytest.raises(isopatch.LimitError, match="use more tiles"):
        distributed.mesh_blocks(GYROID, box=((-20,) * 3, (20,) * 3), edge_length=0.05, tiles=1,
                                out_dir=str(tmp_path), workers=1, memory_limit="200MB", split="planes")


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_the_command_line_writes_tiles_by_planes_as_a_3mf_the_slicer_takes(tmp_path):
    part = tmp_path / "torus.3mf"
    run = subprocess.run([CLI, "mesh", "torus", "--edge-length", "0.04", "--refine", "2", "--tiles", "4", "--split", "planes",
                          "--out-dir", str(tmp_path / "tiles"), "-o", str(part), "--workers", "2"],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    assert "4 tiles" in run.stdout
    cli_manifest = json.loads(open(re.search(r"manifest (\S+?);", run.stdout).group(1)).read())
    ply = tmp_path / "torus.ply"
    manifest = distributed.mesh_blocks("torus", edge_length=0.04, refine=2, tiles=4, out_dir=str(tmp_path / "tiles"),
                                       output=str(ply), workers=1, split="planes")
    assert manifest["vertices"] == cli_manifest["vertices"] and cli_manifest["split"] == "planes"
    vertices, faces = read_ply(ply)
    expect_one_manifold_part(part, vertices, faces)
    run = subprocess.run([CLI, "mesh", "torus", "--split", "planes", "-o", str(tmp_path / "x.ply")],
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 3 and "--split needs --tiles" in run.stderr
    run = subprocess.run([CLI, "mesh", "torus", "--tiles", "2", "--split", "cubes", "--out-dir", str(tmp_path)],
                         capture_output=True, text=True, timeout=60)
    assert run.returncode != 0 and "split" in run.stderr
