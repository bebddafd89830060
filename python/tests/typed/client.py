"""A small typed client of isopatch for the type-checking test (python/tests/test_typing.py): mypy
--strict must find nothing wrong here, so the package's annotations and its compiled module's stub
describe what a user calls."""

from typing import Dict, List

import numpy as np
import numpy.typing as npt

import isopatch
from isopatch import distributed


def sphere(points: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    return np.asarray(np.sum(points * points, axis=1) - 1.0)


def summary(mesh: isopatch.Mesh) -> Dict[str, float]:
    report = mesh.analyze()
    return {"vertices": float(len(mesh.vertices)), "valence_6": float(report["valence"]["share_6"])}


def main() -> List[Dict[str, float]]:
    box = ((-1.2, -1.2, -1.2), (1.2, 1.2, 1.2))
    out = [
        summary(isopatch.mesh("x^2+y^2+z^2-1", box, quality="fine", method="projection", creases="off")),
        summary(isopatch.mesh(sphere, box, edge_length=0.1)),
    ]
    grid = np.zeros((8, 8, 8))
    grid[2:6, 2:6, 2:6] = 1.0
    volume = isopatch.mesh_volume(grid, 0.5, inside="above", quality="preview")
    picture: npt.NDArray[np.uint8] = volume.render(show="mean-curvature", size=(64, 64))
    out.append({"pixels": float(picture.size), "version": float(isopatch.__version__.count("."))})
    manifest = distributed.mesh_blocks("torus", tiles=2, out_dir="out", split="planes", workers=1)
    out.append({"vertices": float(manifest["vertices"])})
    return out
