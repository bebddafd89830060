"""Composite surfaces (.ipatch: I-patches, setback vertex blends) from Python: isopatch.mesh meshes a
.ipatch file along its curves as the command line does (the same vertices), Mesh.from_arrays measures
a mesh against one, and bad requests are refused with the library's errors."""

import os
import subprocess

import numpy as np
import pytest

import isopatch
from conftest import read_ply

CLI = os.environ.get("ISOPATCH_CLI")
EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples")
BLEND = os.path.join(EXAMPLES, "rounded_box.ipatch")


def test_a_blend_is_meshed_along_its_curves_watertight_on_its_patches():
    m = isopatch.mesh(BLEND, edge_length=0.05)
    assert m.stats["refine"]["level"] >= 2
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["outward_oriented"]
    assert report["topology"]["euler_characteristic"] == 2
    assert report["accuracy"]["vertex_distance"]["max"] < 1e-9
    assert report["valence"]["share_6"] > 0.95
    assert report["shape"]["min_angle_degrees"]["min"] > 24.0
    np.testing.assert_allclose(np.linalg.norm(m.normals, axis=1), 1.0, atol=1e-9)
    # Measured again from the arrays against the same composite: the same distances.
    again = isopatch.Mesh.from_arrays(m.vertices, m.faces, BLEND).analyze()
    assert again["accuracy"]["vertex_distance"]["max"] == report["accuracy"]["vertex_distance"]["max"]


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_the_same_vertices_as_the_command_line(tmp_path):
    cube = os.path.join(EXAMPLES, "cube.ipatch")
    run = subprocess.run([CLI, "mesh", cube, "--edge-length", "0.08", "-o", str(tmp_path / "cube.ply")],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    vertices, faces = read_ply(tmp_path / "cube.ply")
    m = isopatch.mesh(cube, edge_length=0.08)
    assert np.array_equal(m.vertices, vertices) and np.array_equal(m.faces, faces)


def test_bad_composite_requests_are_refused(tmp_path):
    with pytest.raises(isopatch.InputError, match="params"):
        isopatch.mesh(BLEND, params={"r": 1.0})
    with pytest.raises(isopatch.IoError):
        isopatch.mesh(str(tmp_path / "absent.ipatch"))
    bad = tmp_path / "bad.ipatch"
    bad.write_text("this is not a composite\n")
    with pytest.raises(isopatch.Error, match="bad.ipatch"):
        isopatch.mesh(str(bad))
