"""Shared helpers of the pytest suite: sampled analytic volumes and their exact normals, and the Dask
cluster of the blocked runs' tests."""

import importlib
import re
import shutil
import subprocess

import numpy as np
import pytest

SPHERE_RADIUS = 0.6
TORUS_RADII = (0.6, 0.25)



def require(module, package):
    """The module `module`, imported; a test failure (never a skip) naming the Debian package when it
    is missing: scripts/install-deps.sh installs every package the tests use, so a missing one is a
    broken installation, not an optional feature."""
    try:
        return importlib.import_module(module)
    except ImportError as error:
        pytest.fail(f"{module} cannot be imported ({error}): the Debian package {package} is missing "
                    "(scripts/install-deps.sh installs it)", pytrace=False)


def sphere(p: np.ndarray) -> np.ndarray:
    return np.linalg.norm(p, axis=1) - SPHERE_RADIUS


def sphere_normal(p: np.ndarray) -> np.ndarray:
    return p / np.linalg.norm(p, axis=1, keepdims=True)


def torus(p: np.ndarray) -> np.ndarray:
    big, small = TORUS_RADII
    q = np.hypot(p[:, 0], p[:, 1]) - big
    return np.hypot(q, p[:, 2]) - small


def torus_normal(p: np.ndarray) -> np.ndarray:
    big, _ = TORUS_RADII
    rho = np.hypot(p[:, 0], p[:, 1])
    centre = np.stack([p[:, 0] / rho * big, p[:, 1] / rho * big, np.zeros(len(p))], axis=1)
    d = p - centre
    return d / np.linalg.norm(d, axis=1, keepdims=True)


def sampled(f, n: int):
    """f on an n^3 grid over [-1, 1]^3: (volume, spacing, origin), volume[i, j, k] at origin + spacing * (i, j, k)."""
    axis = np.linspace(-1.0, 1.0, n)
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    values = f(np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)).reshape(n, n, n)
    step = 2.0 / (n - 1)
    return values, (step, step, step), (-1.0, -1.0, -1.0)


def angle_degrees(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    a = a / np.linalg.norm(a, axis=1, keepdims=True)
    b = b / np.linalg.norm(b, axis=1, keepdims=True)
    return np.degrees(np.arccos(np.clip(np.sum(a * b, axis=1), -1.0, 1.0)))


@pytest.fixture
def unit_box():
    return ((-1.2, -1.2, -1.2), (1.2, 1.2, 1.2))


def read_ply(path):
    """The vertices and faces of a binary PLY as isopatch writes it (double xyz, uchar-int lists)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    v = int(re.search(r"element vertex (\d+)", header).group(1))
    t = int(re.search(r"element face (\d+)", header).group(1))
    vertices = np.frombuffer(data, dtype="<f8", count=3 * v, offset=end).reshape(v, 3)
    records = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("v", "<i4", (3,))]), count=t,
                            offset=end + 24 * v)
    assert (records["n"] == 3).all()
    return vertices, records["v"].astype(np.int64)


def expect_one_manifold_part(part, vertices, faces) -> None:
    """Asserts that Debian's prusa-slicer reads the 3MF `part` as one manifold part whose volume is the
    signed volume of the mesh (vertices, faces)."""
    slicer = shutil.which("prusa-slicer")
    assert slicer, "prusa-slicer is missing (scripts/install-deps.sh installs it)"
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    volume = float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)
    info = subprocess.run([slicer, "--info", str(part)], capture_output=True, text=True, timeout=300)
    assert info.returncode == 0, info.stderr[-2000:]
    fields = dict(re.findall(r"^(\w+) = *(\S+)$", info.stdout, re.M))
    assert fields.get("manifold") == "yes", fields
    assert int(fields["number_of_parts"]) == 1, fields
    assert float(fields["volume"]) == pytest.approx(volume, rel=2e-5), fields


@pytest.fixture(scope="session")
def client():
    """A Dask client of a LocalCluster of two worker processes (one thread each, 127.0.0.1, no
    dashboard), for the tests of blocked runs; closed at the end of the session."""
    distributed_lib = require("distributed", "python3-distributed")
    cluster = distributed_lib.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                           dashboard_address="127.0.0.1:0", scheduler_kwargs={"dashboard": False})
    c = distributed_lib.Client(cluster)
    yield c
    c.close()
    cluster.close()
