"""Lattices capped and shelled by planes, and capped sheets, meshed as blocks on Dask (isopatch.distributed,
docs/distributed.md "Capped lattices"): every part's cut surface refined in blocks with the planes as its
region, closed by its caps on the driver. Watertight, manifold and outward, the creases exactly on the
cap planes, the topology, vertex count, volume and angles of one process; one block is one process's
mesh to the byte; one worker and tasks in reverse order give the same bytes; tiles by planes refuse such
a part in one line; the command line writes a 3MF the slicer takes as one manifold part."""

import json
import os
import subprocess

import numpy as np
import pytest

from conftest import expect_one_manifold_part, read_ply, require
from isopatch import CreaseError, SettingError, distributed

require("distributed", "python3-distributed")

CLI = os.environ.get("ISOPATCH_CLI")
GYROID = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)"
CUBE = "max(max(abs(x),abs(y)),abs(z))"
# One period of the gyroid capped by [-pi, pi]^3: the box passes through the gyroid at its corners and
# edge midpoints (the narrowest corners there are).
CAPPED = "max(%s,%s-pi)" % (GYROID, CUBE)
SHEET = "max(abs(%s)-0.3,%s-pi)" % (GYROID, CUBE)
SHELL = "min(max(%s,%s-pi),max(%s-pi,2.8-%s))" % (GYROID, CUBE, CUBE, CUBE)
BOX = ((-3.4,) * 3, (3.4,) * 3)
EDGE = 0.1


def one_process(formula, path, edge=EDGE):
    run = subprocess.run([CLI, "mesh", formula, "--box", "-3.4,-3.4,-3.4,3.4,3.4,3.4", "--edge-length",
                          str(edge), "-o", str(path)], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]


def analyze(path):
    run = subprocess.run([CLI, "analyze", str(path), "--json"], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    return json.loads(run.stdout)


def volume(vertices, faces):
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def expect_like_one_process(blocked_path, one_path):
    """The blocked part is closed, manifold, outward and free of self-intersections, with the topology of
    one process's, its vertex count within 0.1%, its volume within 1e-4 and its smallest angle within a
    degree; its vertices on the cap planes lie on them to the bit of pi."""
    blocked, one = analyze(blocked_path), analyze(one_path)
    t = blocked["topology"]
    assert t["watertight"] and t["manifold"] and t["outward_oriented"] and t["consistently_oriented"], t
    assert blocked["self_intersections"]["pairs"] == 0
    for key in ("components", "genus"):
        assert t[key] == one["topology"][key], (key, t, one["topology"])
    assert abs(t["vertices"] - one["topology"]["vertices"]) <= 1e-3 * one["topology"]["vertices"]
    assert blocked["shape"]["min_angle_degrees"]["min"] >= one["shape"]["min_angle_degrees"]["min"] - 1.0
    assert blocked["valence"]["share_6"] >= one["valence"]["share_6"] - 0.01
    vertices, faces = read_ply(blocked_path)
    one_vertices, one_faces = read_ply(one_path)
    assert volume(vertices, faces) == pytest.approx(volume(one_vertices, one_faces), rel=1e-4)
    on_planes = np.abs(np.abs(vertices) - np.pi) <= 1e-12
    assert on_planes.any(axis=1).sum() > 0.02 * len(vertices)  # the caps and the creases
    assert (np.abs(vertices) <= np.pi + 1e-12).all()  # nothing outside the part's box


@pytest.fixture(scope="module")
def capped_run(client, tmp_path_factory):
    out = tmp_path_factory.mktemp("capped")
    manifest = distributed.mesh_blocks(CAPPED, box=BOX, edge_length=EDGE, tiles=5, out_dir=str(out),
                                       output=str(out / "capped.ply"), scheduler=client)
    return out, manifest


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_a_capped_gyroid_in_blocks_is_one_processs_part_along_exact_creases(capped_run, tmp_path):
    out, manifest = capped_run
    assert manifest["parts"] == 1 and [c["part"] for c in manifest["cuts"]] == [0]
    cut = manifest["cuts"][0]
    assert cut["level"] >= 2 and len(cut["block_files"]) == 5
    assert manifest["capped"]["caps"] == 6 and manifest["capped"]["crease_vertices"] > 0
    assert manifest["seam_copies_checked"] > 0
    one_process(CAPPED, tmp_path / "one.ply")
    expect_like_one_process(out / "capped.ply", tmp_path / "one.ply")


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_one_block_is_one_processs_mesh_to_the_byte(client, tmp_path):
    distributed.mesh_blocks(CAPPED, box=BOX, edge_length=EDGE, tiles=1, out_dir=str(tmp_path / "blocks"),
                            output=str(tmp_path / "blocked.ply"), scheduler=client)
    one_process(CAPPED, tmp_path / "one.ply")
    assert (tmp_path / "blocked.ply").read_bytes() == (tmp_path / "one.ply").read_bytes()


def test_one_worker_and_tasks_in_reverse_order_give_the_same_bytes(capped_run, tmp_path):
    out, manifest = capped_run
    again = distributed.mesh_blocks(CAPPED, box=BOX, edge_length=EDGE, tiles=5, out_dir=str(tmp_path),
                                    output=str(tmp_path / "again.ply"), workers=1, _test={"reverse": True})
    assert again["computed"] == 5 and again["reused"] == 0
    assert (tmp_path / "again.ply").read_bytes() == (out / "capped.ply").read_bytes()
    assert again["capped"]["sha256"] == manifest["capped"]["sha256"]


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
@pytest.mark.parametrize("formula,parts,cut_parts", [(SHEET, 1, [0, 0]), (SHELL, 2, [1])])
def test_a_capped_sheet_and_a_shelled_lattice_in_blocks_close_every_part(client, tmp_path, formula, parts,
                                                                          cut_parts):
    # The sheet: one part whose cut is the sheet's two walls; the shell: the outer polyhedron's caps and
    # the hollows' cut.
    manifest = distributed.mesh_blocks(formula, box=BOX, edge_length=EDGE, tiles=3, out_dir=str(tmp_path),
                                       output=str(tmp_path / "part.ply"), scheduler=client)
    assert manifest["parts"] == parts and [c["part"] for c in manifest["cuts"]] == cut_parts
    one_process(formula, tmp_path / "one.ply")
    expect_like_one_process(tmp_path / "part.ply", tmp_path / "one.ply")


def test_tiles_by_planes_refuse_a_capped_lattice_in_one_line(client, tmp_path):
    with pytest.raises(SettingError, match="capped by planes is meshed in blocks") as e:
        distributed.mesh_blocks(CAPPED, box=BOX, edge_length=EDGE, tiles=8, split="planes", out_dir=str(tmp_path),
                                scheduler=client)
    assert "\n" not in str(e.value)


def test_a_shape_blocks_cannot_follow_is_refused_with_what_meshes_it_in_each_front_ends_words(client, tmp_path):
    # A gyroid inside a spherical skin: one process meshes it along its creases (docs/lattices.md "Skins"),
    # the blocked run's crease path cannot cut the gyroid's face.
    r = "sqrt(x*x+y*y+z*z)"
    skinned = "max(%s-5,min(%s,4.5-%s))" % (r, GYROID, r)
    with pytest.raises(CreaseError) as e:
        distributed.mesh_blocks(skinned, box=((-5.4,) * 3, (5.4,) * 3), edge_length=0.25, tiles=4,
                                out_dir=str(tmp_path / "py"), scheduler=client)
    message = str(e.value)
    assert "\n" not in message and "without tiles" in message and 'creases="off"' in message
    run = subprocess.run([CLI, "mesh", skinned, "--box", "-5.4,-5.4,-5.4,5.4,5.4,5.4", "--edge-length", "0.25",
                          "--tiles", "4", "--out-dir", str(tmp_path / "cli"), "-o", str(tmp_path / "m.ply")],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 11, run.stderr[-2000:]
    assert "without --tiles" in run.stderr and "--creases off" in run.stderr


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_the_command_line_writes_a_capped_lattices_3mf_the_slicer_takes_as_one_manifold_part(tmp_path):
    part, ply = tmp_path / "part.3mf", tmp_path / "part.ply"
    for path in (part, ply):
        run = subprocess.run([CLI, "mesh", CAPPED, "--box", "-3.4,-3.4,-3.4,3.4,3.4,3.4", "--edge-length", "0.15",
                              "--tiles", "3", "--workers", "2", "--out-dir", str(tmp_path / "blocks"), "-o",
                              str(path)], capture_output=True, text=True, timeout=600)
        assert run.returncode == 0, run.stderr[-2000:]
    vertices, faces = read_ply(ply)
    expect_one_manifold_part(part, vertices, faces)
