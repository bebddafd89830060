"""OpenVDB level sets as input: .vdb files written by Debian's python3-openvdb (pyopenvdb) with
OpenVDB's own level-set tools, meshed by isopatch.mesh_volume from the file and from the grid object,
and by the command line; the same samples as a dense .npy array for comparison; refusals."""

import os
import subprocess
import sys

import numpy as np
import pytest

import isopatch
from conftest import require

vdb = require("pyopenvdb", "python3-openvdb")

CLI = os.environ.get("ISOPATCH_CLI")
VOXEL = 0.05
SPHERE = "sqrt(x^2+y^2+z^2) - 1"
TORUS = "sqrt((sqrt(x^2+y^2) - 1)^2 + z^2) - 0.4"


def torus_polygons(R=1.0, r=0.4, nu=480, nv=240):
    """A fine quad mesh of the torus (its facets far below a voxel) for OpenVDB's mesh-to-level-set."""
    u = np.linspace(0, 2 * np.pi, nu, endpoint=False)
    v = np.linspace(0, 2 * np.pi, nv, endpoint=False)
    U, V = np.meshgrid(u, v, indexing="ij")
    points = np.stack([(R + r * np.cos(V)) * np.cos(U), (R + r * np.cos(V)) * np.sin(U), r * np.sin(V)], -1)
    index = np.arange(nu * nv).reshape(nu, nv)
    nxt_u, nxt_v = np.roll(index, -1, 0), np.roll(index, -1, 1)
    quads = np.stack([index, nxt_u, np.roll(nxt_u, -1, 1), nxt_v], -1).reshape(-1, 4)
    return points.reshape(-1, 3).astype(np.float32), quads.astype(np.uint32)


@pytest.fixture(scope="module")
def grids(tmp_path_factory):
    folder = tmp_path_factory.mktemp("vdb")
    sphere = vdb.createLevelSetSphere(radius=1.0, center=(0, 0, 0), voxelSize=VOXEL, halfWidth=3.0)
    sphere.name = "sphere"
    points, quads = torus_polygons()
    torus = vdb.FloatGrid.createLevelSetFromPolygons(
        points, quads=quads, transform=vdb.createLinearTransform(voxelSize=VOXEL), halfWidth=3.0)
    torus.name = "torus"
    paths = {}
    for g in (sphere, torus):
        paths[g.name] = str(folder / f"{g.name}.vdb")
        vdb.write(paths[g.name], grids=[g])
    both = str(folder / "both.vdb")
    vdb.write(both, grids=[sphere, torus])
    return {"sphere": sphere, "torus": torus, "paths": paths, "both": both, "folder": folder}


def dense(grid):
    """The grid's samples over its active bounds as a dense array, with spacing and origin."""
    lo, hi = grid.evalActiveVoxelBoundingBox()
    array = np.zeros(tuple(h - l + 1 for l, h in zip(lo, hi)), dtype=np.float32)
    grid.copyToArray(array, ijk=lo)
    return array.astype(np.float64), (VOXEL,) * 3, tuple(VOXEL * c for c in lo)


def report(m, formula):
    return isopatch.Mesh.from_arrays(m.vertices, m.faces, formula, box=((-2,) * 3, (2,) * 3)).analyze()


@pytest.mark.parametrize("name,formula", [("sphere", SPHERE), ("torus", TORUS)])
def test_a_level_set_meshes_as_well_as_its_samples_as_npy(grids, name, formula):
    m = isopatch.mesh_volume(grids["paths"][name])
    r = report(m, formula)
    assert r["topology"]["watertight"] and r["topology"]["components"] == 1
    assert r["topology"]["euler_characteristic"] == (2 if name == "sphere" else 0)
    assert r["valence"]["share_6"] >= 0.94, r["valence"]
    assert r["shape"]["min_angle_degrees"]["min"] >= 25.0, r["shape"]["min_angle_degrees"]
    # The vertices are on the spline's zero set: what the mesh reports as |f| at its vertices.
    assert m.stats["projection"]["unprojected"] == 0
    array, spacing, origin = dense(grids[name])
    reference = isopatch.mesh_volume(array, spacing=spacing, origin=origin)
    h_vdb = r["accuracy"]["mean_curvature"]["nrms"]
    h_npy = report(reference, formula)["accuracy"]["mean_curvature"]["nrms"]
    assert h_vdb <= h_npy * 1.05 + 1e-3, (h_vdb, h_npy)
    # Both lie within a small part of a voxel of the analytic surface.
    assert r["accuracy"]["vertex_distance"]["max"] < 0.05 * VOXEL


def test_a_level_inside_the_band_is_the_offset_sphere(grids):
    """The level 0.05 of a distance field is the sphere of radius 1.05: inside the narrow band (0.15) the
    spline follows the stored distances (tests/vdb checks |f| at the vertices themselves)."""
    m = isopatch.mesh_volume(grids["paths"]["sphere"], level=0.05, edge_length=0.08)
    radius = np.linalg.norm(m.vertices, axis=1)
    assert np.abs(radius - 1.05).max() < 0.01 * VOXEL  # the level 0.05 set of a distance field (in its band)


def test_the_grid_object_and_its_file_give_the_same_mesh(grids):
    a = isopatch.mesh_volume(grids["paths"]["torus"])
    b = isopatch.mesh_volume(grids["torus"])
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.faces, b.faces)


def test_two_spheres_far_apart_in_one_grid(tmp_path):
    """Two small spheres 60 units apart (a bounding box of 1200 x 20 x 20 voxels, mostly empty) mesh as
    two spheres; tests/vdb checks that the memory does not grow with the gap."""
    for gap in (3.0, 60.0):
        a = vdb.createLevelSetSphere(radius=0.5, center=(0, 0, 0), voxelSize=VOXEL, halfWidth=3.0)
        b = vdb.createLevelSetSphere(radius=0.5, center=(gap, 0, 0), voxelSize=VOXEL, halfWidth=3.0)
        a.combine(b, lambda x, y: min(x, y))
        a.name = "pair"
        path = str(tmp_path / f"pair{gap}.vdb")
        vdb.write(path, grids=[a])
        m = isopatch.mesh_volume(path, edge_length=0.08)
        r = m.analyze()
        assert r["topology"]["components"] == 2 and r["topology"]["watertight"]


def test_grids_are_listed_and_chosen_by_name(grids):
    listed = isopatch.vdb_grids(grids["both"])
    assert [g["name"] for g in listed] == ["sphere", "torus"]
    assert all(g["grid_class"] == "level set" and g["value_type"] == "float" for g in listed)
    with pytest.raises(isopatch.InputError, match="name the one to mesh"):
        isopatch.mesh_volume(grids["both"])
    with pytest.raises(isopatch.InputError, match="no grid 'cube'"):
        isopatch.mesh_volume(grids["both"], grid="cube")
    m = isopatch.mesh_volume(grids["both"], grid="torus", edge_length=0.1)
    assert m.analyze()["topology"]["euler_characteristic"] == 0


def test_a_fog_volume_with_inside_above(tmp_path):
    """A density grid (values above the level inside) meshes outward with inside='above'."""
    fog = vdb.FloatGrid()
    fog.name = "density"
    n = 40
    axis = (np.arange(n) - n // 2) * VOXEL  # voxel (i, j, k) sits at (i, j, k) * VOXEL
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    fog.copyFromArray(np.clip(1.0 - np.sqrt(x**2 + y**2 + z**2) / 0.6, 0, 1).astype(np.float32), ijk=(-20, -20, -20))
    fog.transform = vdb.createLinearTransform(voxelSize=VOXEL)
    path = str(tmp_path / "fog.vdb")
    vdb.write(path, grids=[fog])
    m = isopatch.mesh_volume(path, level=0.5, inside="above", edge_length=0.05)
    r = m.analyze()
    assert r["topology"]["watertight"] and r["topology"]["outward_oriented"]
    assert np.abs(np.linalg.norm(m.vertices, axis=1) - 0.3).max() < 0.01


@pytest.mark.parametrize("content,match", [
    (b"", "not an OpenVDB file"),
    (b"ply\nformat ascii 1.0\n", "not an OpenVDB file"),
    (b" BDV" + bytes(4) + bytes(range(200)), "bad.vdb: "),
])
def test_hostile_files_are_refused_in_one_line(tmp_path, content, match):
    path = tmp_path / "bad.vdb"
    path.write_bytes(content)
    with pytest.raises(isopatch.IoError, match=match) as info:
        isopatch.mesh_volume(str(path))
    assert "\n" not in str(info.value)


def test_a_truncated_file_and_unsupported_grids_are_refused(grids, tmp_path):
    data = open(grids["paths"]["sphere"], "rb").read()
    cut = tmp_path / "cut.vdb"
    cut.write_bytes(data[: len(data) // 2])
    with pytest.raises(isopatch.IoError):
        isopatch.mesh_volume(str(cut))
    vectors = vdb.Vec3SGrid()
    vectors.name = "velocity"
    vectors.copyFromArray(np.ones((4, 4, 4, 3), dtype=np.float32))
    path = str(tmp_path / "vectors.vdb")
    vdb.write(path, grids=[vectors])
    with pytest.raises(isopatch.IoError, match="float or double"):
        isopatch.mesh_volume(path, grid="velocity")
    with pytest.raises(isopatch.NoSurfaceError, match="crosses level 5"):
        isopatch.mesh_volume(grids["paths"]["sphere"], level=5.0)
    with pytest.raises(isopatch.InputError, match="transform"):
        isopatch.mesh_volume(grids["paths"]["sphere"], spacing=(1, 1, 1))


@pytest.mark.skipif(CLI is None, reason="the command-line tool is not built")
def test_the_command_line_meshes_a_vdb_as_python_does(grids, tmp_path):
    out = tmp_path / "torus.ply"
    subprocess.run([CLI, "mesh", grids["both"], "--grid", "torus", "-o", str(out), "-q"], check=True, timeout=300)
    mine = tmp_path / "python.ply"
    isopatch.mesh_volume(grids["both"], grid="torus").write(str(mine))
    assert out.read_bytes() == mine.read_bytes()
    run = subprocess.run([CLI, "mesh", grids["both"], "-o", str(out)], capture_output=True, text=True, timeout=300)
    assert run.returncode != 0 and "--grid NAME" in run.stderr
    bad = tmp_path / "bad.vdb"
    bad.write_bytes(b"nothing")
    run2 = subprocess.run([CLI, "mesh", str(bad), "-o", str(out)], capture_output=True, text=True, timeout=300)
    assert run2.returncode not in (0, run.returncode) and run2.stderr.count("\n") == 1


def test_a_volume_file_path_meshes_as_its_array(tmp_path):
    """mesh_volume of a .npy path is mesh_volume of the array read_volume gives (spacing and origin
    given, as a .npy file holds none)."""
    axis = np.linspace(-1, 1, 24)
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    path = str(tmp_path / "ball.npy")
    np.save(path, np.sqrt(x**2 + y**2 + z**2) - 0.6)
    h = 2 / 23
    a = isopatch.mesh_volume(path, spacing=(h,) * 3, origin=(-1,) * 3, edge_length=0.15)
    b = isopatch.mesh_volume(np.load(path), spacing=(h,) * 3, origin=(-1,) * 3, edge_length=0.15)
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.faces, b.faces)
    with pytest.raises(isopatch.InputError, match="grid="):
        isopatch.mesh_volume(path, grid="x")


def test_openvdb_is_loaded_only_when_a_vdb_is_read(grids):
    """OpenVDB is a plugin (isopatch_openvdb.so) loaded on the first .vdb read: importing isopatch and
    meshing a formula do not map libopenvdb (its relocations were most of the tool's start-up)."""
    script = ("import isopatch, sys\n"
              "def mapped():\n"
              "    return 'libopenvdb' in open('/proc/self/maps').read()\n"
              "isopatch.mesh('sphere', edge_length=0.3)\n"
              "before = mapped()\n"
              "grids = isopatch.vdb_grids(sys.argv[1])\n"
              "print(before, mapped(), [g['name'] for g in grids])\n")
    run = subprocess.run([sys.executable, "-c", script, grids["both"]], capture_output=True, text=True,
                         timeout=120, check=True)
    assert run.stdout.split() == ["False", "True", "['sphere',", "'torus']"]


@pytest.mark.skipif(CLI is None, reason="the command-line tool is not built")
def test_the_command_line_loads_openvdb_only_for_a_vdb(grids, tmp_path):
    loaded = {}
    for name, command in {"version": [CLI, "--version"],
                          "formula": [CLI, "mesh", "sphere", "-o", str(tmp_path / "s.ply"), "-q"],
                          "vdb": [CLI, "mesh", grids["paths"]["sphere"], "-o", str(tmp_path / "v.ply"), "-q"]}.items():
        run = subprocess.run(command, capture_output=True, text=True, timeout=300,
                             env={**os.environ, "LD_DEBUG": "files"})
        assert run.returncode == 0, run.stderr[-2000:]
        loaded[name] = "file=libopenvdb" in run.stderr
    assert loaded == {"version": False, "formula": False, "vdb": True}


@pytest.mark.skipif(CLI is None, reason="the command-line tool is not built")
def test_a_broken_openvdb_plugin_is_one_line_and_an_input_output_error(grids, tmp_path):
    broken = tmp_path / "isopatch_openvdb.so"
    broken.write_bytes(b"not a shared object")
    env = {**os.environ, "ISOPATCH_OPENVDB_PLUGIN": str(broken)}
    run = subprocess.run([CLI, "mesh", grids["paths"]["sphere"], "-o", str(tmp_path / "v.ply")],
                         capture_output=True, text=True, timeout=300, env=env)
    unreadable = subprocess.run([CLI, "mesh", str(tmp_path / "missing.vdb"), "-o", str(tmp_path / "v.ply")],
                                capture_output=True, text=True, timeout=300)
    assert run.returncode == unreadable.returncode != 0  # the exit code of an input/output error
    assert run.stderr.count("\n") == 1 and "cannot load the .vdb reader" in run.stderr
    assert str(broken) in run.stderr and not (tmp_path / "v.ply").exists()
    # The formula surfaces do not need the plugin at all.
    ok = subprocess.run([CLI, "mesh", "sphere", "-o", str(tmp_path / "s.ply"), "-q"], capture_output=True,
                        text=True, timeout=300, env=env)
    assert ok.returncode == 0, ok.stderr
