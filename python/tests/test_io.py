"""Files and interop: write in every format, meshio, analyze, render, volume files, the CLI."""

import os
import subprocess

import numpy as np
import pytest

import isopatch

from conftest import sampled, sphere, require

CLI = os.environ.get("ISOPATCH_CLI")


@pytest.fixture(scope="module")
def sphere_mesh():
    return isopatch.mesh("x^2+y^2+z^2-1", box=((-1.2,) * 3, (1.2,) * 3), edge_length=0.15)


@pytest.mark.parametrize("extension", ["ply", "obj", "off", "stl"])
def test_write_every_format(sphere_mesh, tmp_path, extension):
    path = tmp_path / f"sphere.{extension}"
    sphere_mesh.write(str(path))
    meshio = require("meshio", "python3-meshio")
    back = meshio.read(str(path))
    assert len(back.cells_dict["triangle"]) == len(sphere_mesh.faces)
    if extension != "stl":
        np.testing.assert_allclose(back.points, sphere_mesh.vertices, atol=1e-12)


def test_write_fields_and_errors(sphere_mesh, tmp_path):
    path = tmp_path / "fields.ply"
    sphere_mesh.write(str(path), fields=True)
    assert b"property float mean_curvature_exact" in path.read_bytes()[:2000]
    with pytest.raises(isopatch.IoError):
        sphere_mesh.write(str(tmp_path / "no" / "such" / "dir.ply"))
    with pytest.raises(isopatch.IoError):
        sphere_mesh.write(str(tmp_path / "mesh.xyz"))


def test_meshio_one_liner(sphere_mesh, tmp_path):
    meshio = require("meshio", "python3-meshio")
    m = meshio.Mesh(sphere_mesh.vertices, [("triangle", sphere_mesh.faces)], point_data=sphere_mesh.fields)
    m.write(str(tmp_path / "sphere.vtu"))
    back = meshio.read(str(tmp_path / "sphere.vtu"))
    np.testing.assert_allclose(back.point_data["mean_curvature_exact"], sphere_mesh.fields["mean_curvature_exact"])


def test_analyze_and_render(sphere_mesh, tmp_path):
    report = sphere_mesh.analyze()
    assert report["topology"]["watertight"] and report["topology"]["genus"] == 0
    assert report["accuracy"]["vertex_distance"]["max"] < 1e-9
    assert "accuracy" not in sphere_mesh.analyze(surface=False)
    image = sphere_mesh.render(size=(120, 90))
    assert image.shape == (90, 120, 3) and image.dtype == np.uint8
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 20  # shaded, not blank
    path = tmp_path / "curvature.png"
    field = sphere_mesh.render(str(path), show="mean-curvature", size=(64, 64))
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not np.array_equal(field, sphere_mesh.render(show="shaded", size=(64, 64)))
    with pytest.raises(isopatch.InputError):
        sphere_mesh.render(show="field", field="no_such_field")
    with pytest.raises(isopatch.InputError):
        sphere_mesh.render(show="sketch")


def test_nrrd_gzip_with_spacing_and_origin(tmp_path):
    import gzip

    volume, spacing, origin = sampled(sphere, 20)
    # NRRD lists the fastest axis first: x fastest is numpy's Fortran order of volume[x, y, z].
    data = gzip.compress(np.asfortranarray(volume).astype("<f8").tobytes(order="F"))
    header = (
        "NRRD0004\ntype: double\ndimension: 3\nsizes: 20 20 20\nencoding: gzip\nendian: little\n"
        f"space directions: ({spacing[0]},0,0) (0,{spacing[1]},0) (0,0,{spacing[2]})\n"
        f"space origin: ({origin[0]},{origin[1]},{origin[2]})\n\n"
    )
    path = tmp_path / "sphere.nrrd"
    path.write_bytes(header.encode() + data)
    back, s, o = isopatch.read_volume(str(path))
    np.testing.assert_array_equal(back, volume)
    np.testing.assert_allclose(s, spacing)
    np.testing.assert_allclose(o, origin)
    m = isopatch.mesh_volume(back, spacing=s, origin=o)
    np.testing.assert_allclose(np.linalg.norm(m.vertices, axis=1), 0.6, atol=2e-3)
    path.write_bytes(header.encode() + data[: len(data) // 2])
    with pytest.raises(isopatch.IoError, match="truncated"):
        isopatch.read_volume(str(path))


def test_volume_files_and_the_command_line(tmp_path):
    volume, spacing, origin = sampled(sphere, 24)
    path = tmp_path / "sphere.npy"
    np.save(path, volume.astype(np.float32))
    back, s, o = isopatch.read_volume(str(path))
    np.testing.assert_array_equal(back, volume.astype(np.float32))
    assert s == (1.0, 1.0, 1.0) and o == (0.0, 0.0, 0.0)
    np.save(tmp_path / "flat.npy", volume[0])
    with pytest.raises(isopatch.IoError, match="2 dimensions"):
        isopatch.read_volume(str(tmp_path / "flat.npy"))
    if not CLI:
        return
    out = tmp_path / "sphere.ply"
    box = ",".join(str(v) for v in (-1, -1, -1, 1, 1, 1))
    r = subprocess.run([CLI, "mesh", str(path), "--spacing", ",".join(map(str, spacing)), "--origin",
                        ",".join(map(str, origin)), "-o", str(out), "-q", "--box", box], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    meshio = require("meshio", "python3-meshio")
    points = meshio.read(str(out)).points
    np.testing.assert_allclose(np.linalg.norm(points, axis=1), 0.6, atol=2e-3)
    r = subprocess.run([CLI, "mesh", str(tmp_path / "flat.npy"), "-o", str(out)], capture_output=True, text=True)
    assert r.returncode == 6 and "2 dimensions" in r.stderr
    r = subprocess.run([CLI, "mesh", str(path), "--level", "9", "-o", str(out)], capture_output=True, text=True)
    assert r.returncode == 8 and "no sample of the volume crosses level 9" in r.stderr


def test_from_arrays_measures_any_mesh():
    measure = require("skimage.measure", "python3-skimage")
    volume, spacing, origin = sampled(sphere, 32)
    verts, faces, _, _ = measure.marching_cubes(volume, 0.0, spacing=spacing)
    theirs = isopatch.Mesh.from_arrays(verts + np.asarray(origin), faces, "sqrt(x^2+y^2+z^2) - 0.6",
                                       box=((-1,) * 3, (1,) * 3))
    ours = isopatch.mesh_volume(volume, spacing=spacing, origin=origin)
    a, b = theirs.analyze(), ours.analyze()
    assert a["topology"]["triangles"] == len(faces)
    assert a["shape"]["min_angle_degrees"]["min"] < b["shape"]["min_angle_degrees"]["min"]
    assert a["valence"]["share_6"] < b["valence"]["share_6"]
    np.testing.assert_allclose(np.linalg.norm(theirs.normals, axis=1), 1.0)
    with pytest.raises(isopatch.InputError, match="refers to vertex 99"):
        isopatch.Mesh.from_arrays(verts[:10], np.array([[0, 1, 99]]), "sqrt(x^2+y^2+z^2) - 0.6",
                                  box=((-1,) * 3, (1,) * 3))
    with pytest.raises(isopatch.InputError, match=r"\(V, 3\)"):
        isopatch.Mesh.from_arrays(verts[:, :2], faces, "torus")
