"""Meshes for printing read by a real slicer: PrusaSlicer (Debian's prusa-slicer) finds each .3mf and
.stl written by isopatch to be one manifold part whose volume is the mesh's own."""

import os
import re
import shutil
import subprocess

import numpy as np
import pytest

import isopatch
from conftest import require

CLI = os.environ.get("ISOPATCH_CLI")
EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")


def enclosed_volume(vertices: np.ndarray, faces: np.ndarray) -> float:
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def slicer_info(path) -> dict:
    slicer = shutil.which("prusa-slicer")
    assert slicer, "prusa-slicer is missing (scripts/install-deps.sh installs it)"
    run = subprocess.run([slicer, "--info", str(path)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    return dict(re.findall(r"^(\w+) = *(\S+)$", run.stdout, re.M))


def check_part(path, volume: float) -> None:
    info = slicer_info(path)
    assert info.get("manifold") == "yes", info
    assert int(info["number_of_parts"]) == 1, info
    # The slicer prints six decimals, the files hold floats (STL) or six decimals (3MF).
    assert float(info["volume"]) == pytest.approx(volume, rel=2e-5, abs=2e-6), info


@pytest.mark.parametrize(
    "surface,box",
    [("torus", None), ("max(max(abs(x),abs(y)),abs(z))-1", ((-1.5,) * 3, (1.5,) * 3)),
     # A gyroid lattice capped by its box (docs/lattices.md): one closed part with sharp caps.
     ("max(sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x),max(max(abs(x),abs(y)),abs(z))-pi)", ((-3.3,) * 3, (3.3,) * 3)),
     # The same lattice cut by a ball: two curved faces joined along their crease.
     ("max(sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x),x^2+y^2+z^2-9)", ((-3.4,) * 3, (3.4,) * 3))],
    ids=["torus", "cube_with_creases", "capped_gyroid", "ball_cut_gyroid"],
)
@pytest.mark.parametrize("extension", ["3mf", "stl"])
def test_a_slicer_reads_one_manifold_part_of_the_meshs_volume(tmp_path, surface, box, extension):
    m = isopatch.mesh(surface, box=box)
    path = tmp_path / f"part.{extension}"
    m.write(str(path))
    check_part(path, enclosed_volume(m.vertices, m.faces))


@pytest.mark.skipif(CLI is None, reason="the command-line tool is not built")
def test_a_composite_surface_written_as_3mf_by_the_command_line(tmp_path):
    meshio = require("meshio", "python3-meshio")
    example = os.path.join(EXAMPLES, "rounded_box.ipatch")
    part, ply = tmp_path / "box.3mf", tmp_path / "box.ply"
    for out in (part, ply):
        subprocess.run([CLI, "mesh", example, "-o", str(out), "-q"], check=True, timeout=300)
    back = meshio.read(str(ply))
    volume = enclosed_volume(back.points, back.cells_dict["triangle"])
    assert volume > 0
    check_part(part, volume)
    # The same mesh gives the same package, byte for byte.
    again = tmp_path / "again.3mf"
    subprocess.run([CLI, "mesh", example, "-o", str(again), "-q"], check=True, timeout=300)
    assert part.read_bytes() == again.read_bytes()
