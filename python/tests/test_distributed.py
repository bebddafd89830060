"""Blocked meshing on Dask (isopatch.distributed): a closed gyroid lattice of 8 blocks and 100k+
vertices on a LocalCluster of two worker processes (one thread each, 127.0.0.1, no dashboard) is
watertight across the seams, on f = 0, of the topology and quality of one process, the same bytes with
one worker and tasks in reverse order, survives a worker killed in the middle and workers killed three
times at random, reuses finished blocks when run again (also after its driver was killed), refuses a block larger than its worker's memory, and prints as one manifold part."""

import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import isopatch
from conftest import expect_one_manifold_part, read_ply, require
from isopatch import _blocks, distributed

distributed_lib = require("distributed", "python3-distributed")

CLI = os.environ.get("ISOPATCH_CLI")
# A gyroid lattice closed by a smooth envelope (f grows past the sphere of radius 9): genus 36.
LATTICE = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)+((x^2+y^2+z^2)/81)^4"
BOX = ((-10.5, -10.5, -10.5), (10.5, 10.5, 10.5))
EDGE = 0.14
TILES = 8


def lattice_f(p: np.ndarray):
    x, y, z = p[:, 0], p[:, 1], p[:, 2]
    r = (x * x + y * y + z * z) / 81.0
    f = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x) + r ** 4
    g = np.stack([
        np.cos(x) * np.cos(y) - np.sin(z) * np.sin(x) + 8.0 * r ** 3 * x / 81.0,
        -np.sin(x) * np.sin(y) + np.cos(y) * np.cos(z) + 8.0 * r ** 3 * y / 81.0,
        -np.sin(y) * np.sin(z) + np.cos(z) * np.cos(x) + 8.0 * r ** 3 * z / 81.0,
    ], axis=1)
    return f, g


@pytest.fixture(scope="module")
def clean_run(client, tmp_path_factory):
    out = tmp_path_factory.mktemp("clean")
    manifest = distributed.mesh_blocks(LATTICE, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(out),
                                       output=str(out / "lattice.ply"), scheduler=client)
    return out, manifest


def test_the_lattice_is_watertight_across_blocks_on_the_surface_and_as_good_as_one_process(clean_run):
    out, manifest = clean_run
    # Dask may run a task twice (a stolen task, a lost result): the second run finds the first's file.
    assert manifest["blocks"] == TILES and manifest["computed"] + manifest["reused"] == TILES
    assert manifest["vertices"] >= 100_000
    assert manifest["seam_copies_checked"] > 0
    vertices, faces = read_ply(out / "lattice.ply")
    assert len(vertices) == manifest["vertices"] and len(faces) == manifest["triangles"]
    # Every edge in exactly two triangles, once in each direction (consistently oriented).
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    keys = directed[:, 0] * len(vertices) + directed[:, 1]
    assert len(np.unique(keys)) == len(keys), "an edge is traversed twice the same way"
    reverse = directed[:, 1] * len(vertices) + directed[:, 0]
    assert np.isin(reverse, keys).all(), "an edge has one triangle (a crack between blocks)"
    assert len(np.unique(vertices, axis=0)) == len(vertices), "two vertices at one position"
    f, g = lattice_f(vertices)
    assert np.max(np.abs(f) / np.linalg.norm(g, axis=1)) < 1e-9
    # Topology and quality against one process with the same settings.
    blocked = isopatch.Mesh.from_arrays(vertices, faces, LATTICE, box=BOX).analyze()
    one = isopatch.mesh(LATTICE, box=BOX, edge_length=EDGE).analyze()
    assert blocked["topology"]["euler_characteristic"] == one["topology"]["euler_characteristic"]
    assert blocked["topology"]["components"] == one["topology"]["components"]
    assert blocked["topology"]["outward_oriented"] and blocked["topology"]["watertight"]
    assert blocked["self_intersections"]["pairs"] == 0
    assert blocked["valence"]["share_6"] > one["valence"]["share_6"] - 0.01
    assert blocked["shape"]["min_angle_degrees"]["min"] > min(25.0, one["shape"]["min_angle_degrees"]["min"] - 1.0)
    # The band along the seams is reported apart, and every block file is in the manifest.
    assert 0 < manifest["seam_band_vertices"] < manifest["vertices"]
    on_disk = json.loads(open(manifest["manifest"]).read())
    for entry in on_disk["block_files"]:
        assert isopatch._blocks.file_digest(str(out / entry["file"])) == entry["sha256"]


def test_one_worker_and_tasks_in_reverse_order_give_the_same_bytes(clean_run, tmp_path):
    out, _ = clean_run
    manifest = distributed.mesh_blocks(LATTICE, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                       output=str(tmp_path / "one.ply"), workers=1, _test={"reverse": True})
    assert manifest["computed"] + manifest["reused"] == TILES and manifest["computed"] >= 1
    assert (tmp_path / "one.ply").read_bytes() == (out / "lattice.ply").read_bytes()


def test_a_worker_killed_in_the_middle_is_replaced_and_the_job_completes(client, clean_run, tmp_path):
    out, _ = clean_run
    marker = tmp_path / "killed"
    manifest = distributed.mesh_blocks(LATTICE, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                       output=str(tmp_path / "after_kill.ply"), scheduler=client,
                                       _test={"kill_marker": str(marker), "kill_block": 3})
    assert marker.exists(), "the task did not kill its worker"
    # The lost worker's finished results are lost with it and run again: their files are found.
    assert manifest["computed"] + manifest["reused"] == TILES and manifest["computed"] >= 1
    assert (tmp_path / "after_kill.ply").read_bytes() == (out / "lattice.ply").read_bytes()


def test_workers_killed_three_times_at_random_leave_the_same_bytes(client, clean_run, tmp_path):
    out, _ = clean_run
    seed = int.from_bytes(os.urandom(4), "little")
    blocks = sorted(random.Random(seed).sample(range(TILES), 3))
    marker = tmp_path / "killed"
    manifest = distributed.mesh_blocks(LATTICE, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                       output=str(tmp_path / "after_kills.ply"), scheduler=client,
                                       _test={"kill_marker": str(marker), "kill_blocks": blocks})
    for block in blocks:
        assert (tmp_path / ("killed-%d" % block)).exists(), "block %d did not kill its worker (seed %d)" % (block, seed)
    assert manifest["computed"] + manifest["reused"] == TILES
    assert (tmp_path / "after_kills.ply").read_bytes() == (out / "lattice.ply").read_bytes(), "seed %d" % seed
    for b in manifest["block_files"]:  # the manifest's checksums are the files'
        assert _blocks.file_digest(str(tmp_path / b["file"])) == b["sha256"]


def test_a_driver_killed_and_run_again_reuses_its_blocks_and_ends_with_the_same_bytes(client, clean_run, tmp_path):
    out, _ = clean_run
    # The driver and its local cluster in a session of their own, killed as a whole (SIGKILL: no clean-up)
    # once two blocks are written.
    command = [sys.executable, "-m", "isopatch.distributed", LATTICE, "--tiles", str(TILES), "--out-dir",
               str(tmp_path), "-o", str(tmp_path / "lattice.ply"), "--box=" + ",".join(str(v) for v in BOX[0] + BOX[1]),
               "--edge-length", str(EDGE), "--workers", "2"]
    driver = subprocess.Popen(command, start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 120
    try:
        while time.monotonic() < deadline and driver.poll() is None and \
                len([n for n in os.listdir(tmp_path) if n.startswith("block-") and n.endswith(".npz")]) < 2:
            time.sleep(0.02)
    finally:
        try:
            os.killpg(driver.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        driver.wait(timeout=60)
    assert driver.returncode == -signal.SIGKILL, driver.stderr.read().decode()[-2000:]
    assert not [n for n in os.listdir(tmp_path) if n.startswith("manifest-")], "the driver finished before the kill"
    done = {n for n in os.listdir(tmp_path) if n.startswith("block-") and n.endswith(".npz")}
    assert len(done) >= 2
    again = distributed.mesh_blocks(LATTICE, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                    output=str(tmp_path / "lattice.ply"), scheduler=client)
    assert {b["file"] for b in again["block_files"] if b["reused"]} >= done
    assert (tmp_path / "lattice.ply").read_bytes() == (out / "lattice.ply").read_bytes()
    for b in again["block_files"]:
        assert _blocks.file_digest(str(tmp_path / b["file"])) == b["sha256"]


def test_a_driver_run_again_reuses_finished_blocks(client, clean_run, tmp_path):
    out, first = clean_run
    for name in os.listdir(out):
        if name.startswith(("base-", "block-")):
            shutil.copy(out / name, tmp_path / name)
    os.remove(tmp_path / first["block_files"][5]["file"])  # as if the driver stopped before block 5
    (tmp_path / first["block_files"][6]["file"]).write_bytes(b"not a block")  # a damaged file is made again
    again = distributed.mesh_blocks(LATTICE, box=BOX, edge_length=EDGE, tiles=TILES, out_dir=str(tmp_path),
                                    output=str(tmp_path / "again.ply"), scheduler=client)
    made = {b["block"] for b in again["block_files"] if not b["reused"]}
    assert made <= {5, 6}, again["block_files"]  # every other block reused
    for block in (5, 6):  # made again: whole block files now
        with np.load(tmp_path / first["block_files"][block]["file"]) as data:
            assert data["positions"].shape[0] == again["block_files"][block]["vertices"] > 0
    assert (tmp_path / "again.ply").read_bytes() == (out / "lattice.ply").read_bytes()
    # Other settings are another job: nothing reused.
    other = distributed.mesh_blocks(LATTICE, box=BOX, edge_length=0.3, tiles=TILES, out_dir=str(tmp_path),
                                    scheduler=client)
    assert other["reused"] == 0 and other["hash"] != again["hash"]


def test_a_block_larger_than_its_workers_memory_is_refused_with_advice(tmp_path):
    with pytest.raises(isopatch.LimitError, match="use more blocks"):
        distributed.mesh_blocks(LATTICE, box=BOX, edge_length=0.05, tiles=1, out_dir=str(tmp_path), workers=1,
                                memory_limit="200MB")


def test_bad_requests_are_refused_in_one_line(client, tmp_path):
    with pytest.raises(isopatch.InputError):
        distributed.mesh_blocks(LATTICE, box=BOX, tiles=0, out_dir=str(tmp_path), scheduler=client)
    with pytest.raises(isopatch.InputError, match="scheduler"):
        distributed.mesh_blocks(LATTICE, box=BOX, tiles=2, out_dir=str(tmp_path), scheduler="udp://x")
    with pytest.raises(isopatch.ParseError):
        distributed.mesh_blocks("x^2+", box=BOX, tiles=2, out_dir=str(tmp_path), scheduler=client)
    with pytest.raises(isopatch.InputError, match="unknown setting"):
        distributed.mesh_blocks(LATTICE, box=BOX, tiles=2, out_dir=str(tmp_path), scheduler=client, grid=3)


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_the_command_line_writes_a_3mf_the_slicer_takes_as_one_manifold_part(tmp_path):
    part = tmp_path / "lattice.3mf"
    run = subprocess.run([CLI, "mesh", LATTICE, "--box", "-10.5,-10.5,-10.5,10.5,10.5,10.5", "--edge-length",
                          "0.3", "--tiles", "4", "--out-dir", str(tmp_path / "blocks"), "-o", str(part),
                          "--workers", "2"], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    manifest = json.loads(open(re.search(r"manifest (\S+?);", run.stdout).group(1)).read())
    ply = tmp_path / "lattice.ply"
    distributed.mesh_blocks(LATTICE, box=BOX, edge_length=0.3, tiles=4, out_dir=str(tmp_path / "blocks"),
                            output=str(ply), workers=1)
    vertices, faces = read_ply(ply)
    expect_one_manifold_part(part, vertices, faces)
    assert manifest["vertices"] == len(vertices)


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_the_command_line_refuses_what_blocks_do_not_keep(tmp_path):
    run = subprocess.run([CLI, "mesh", "torus", "--tiles", "2", "--out-dir", str(tmp_path), "--region",
                          "sphere:0,0,0,1"], capture_output=True, text=True, timeout=60)
    assert run.returncode == 3 and "--tiles" in run.stderr
    run = subprocess.run([CLI, "mesh", "torus", "--tiles", "2"], capture_output=True, text=True, timeout=60)
    assert run.returncode == 3 and "--out-dir" in run.stderr
