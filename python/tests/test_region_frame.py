"""Regions and frames in Python as on the command line: isopatch.mesh(..., region=, frame=) gives the
tool's mesh of the same settings to the bit, takes a region as text or as planes, a frame as text or
angles, gives a formula without a box a bounded region's bounds, and refuses what the tool refuses."""

import os
import subprocess

import numpy as np
import pytest

import isopatch
from conftest import read_ply

CLI = os.environ.get("ISOPATCH_CLI")
SPHERE = "x^2+y^2+z^2-0.36"
CUBE = "1,0,0,-0.5;-1,0,0,-0.5;0,1,0,-0.5;0,-1,0,-0.5;0,0,1,-0.5;0,0,-1,-0.5"
PLANES = [(1, 0, 0, -0.5), (-1, 0, 0, -0.5), (0, 1, 0, -0.5), (0, -1, 0, -0.5), (0, 0, 1, -0.5), (0, 0, -1, -0.5)]


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")
def test_a_region_and_a_frame_give_the_command_lines_mesh(tmp_path):
    path = tmp_path / "cut.ply"
    run = subprocess.run([CLI, "mesh", SPHERE, "--region", CUBE, "--frame", "30,20,10", "--edge-length", "0.05",
                          "-q", "-o", str(path)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    vertices, faces = read_ply(path)
    m = isopatch.mesh(SPHERE, region=CUBE, frame="30,20,10", edge_length=0.05)
    assert np.array_equal(m.vertices, vertices) and np.array_equal(m.faces, faces)
    # The sphere cut by the cube: every vertex inside it, some on its faces.
    assert np.abs(m.vertices).max() <= 0.5 + 1e-12
    assert (np.abs(np.abs(m.vertices) - 0.5) < 1e-12).any()


def test_planes_and_angles_are_the_same_as_their_text():
    text = isopatch.mesh(SPHERE, region=CUBE, frame="30,20,10", edge_length=0.08)
    numbers = isopatch.mesh(SPHERE, region=PLANES, frame=(30, 20, 10), edge_length=0.08)
    assert np.array_equal(text.vertices, numbers.vertices) and np.array_equal(text.faces, numbers.faces)
    boxed = isopatch.mesh("torus", region=[(0, 0, 1, -0.1)], edge_length=0.08)  # the catalogue's own box
    assert boxed.vertices[:, 2].max() <= 0.1 + 1e-12


def test_what_the_tool_refuses_is_refused():
    with pytest.raises(isopatch.SettingError, match="unbounded"):
        isopatch.mesh(SPHERE, region=[(0, 0, 1, -0.1)])  # a formula without a box, an unbounded region
    with pytest.raises(isopatch.InputError, match="no normal"):
        isopatch.mesh("torus", region=[(0, 0, 0, 1)])
    with pytest.raises(isopatch.InputError):
        isopatch.mesh("torus", region="1,2,3")
    with pytest.raises(isopatch.InputError, match="finite"):
        isopatch.mesh("torus", frame=(1.0, float("nan"), 0.0))
    with pytest.raises(isopatch.InputError, match="formulas and catalogue names"):
        isopatch.mesh(lambda p: p[:, 0], ((-1,) * 3, (1,) * 3), region=CUBE)
    with pytest.raises(isopatch.SettingError):
        isopatch.mesh("torus", region=CUBE, method="mc")
