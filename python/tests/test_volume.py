"""mesh_volume: sampled sphere and torus against the analytic surfaces and against scikit-image."""

import numpy as np
import pytest

import isopatch

from conftest import angle_degrees, sampled, sphere, sphere_normal, torus, torus_normal, require

# The largest distance to the analytic surface of the vertices (which lie on the samples' interpolant)
# for volumes of n^3 samples over [-1, 1]^3, and the largest angle between the returned normals and the
# analytic ones: the interpolation error, which falls like h^4 (h = 2 / (n - 1)). Measured (bench and
# docs/python.md): sphere 5e-6 and 7e-8, torus 8e-4 and 2e-5; normals within 0.7 degrees.
CASES = [
    (sphere, sphere_normal, 32, 0, 2e-5, 0.05),
    (sphere, sphere_normal, 64, 0, 5e-7, 0.01),
    (torus, torus_normal, 32, 1, 2e-3, 1.5),
    (torus, torus_normal, 64, 1, 1e-4, 0.1),
]


@pytest.mark.parametrize("f, normal, n, genus, distance, normal_degrees", CASES)
def test_sampled_surfaces(f, normal, n, genus, distance, normal_degrees):
    volume, spacing, origin = sampled(f, n)
    m = isopatch.mesh_volume(volume, level=0.0, spacing=spacing, origin=origin)
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["genus"] == genus
    assert report["valence"]["share_6"] >= 0.90
    assert report["shape"]["min_angle_degrees"]["min"] >= 20.0
    assert np.abs(f(m.vertices)).max() < distance
    assert report["accuracy"]["vertex_distance"]["max"] < 1e-9  # on the interpolant itself

    # Normals against the analytic ones, and against scikit-image's on the same volume.
    ours = angle_degrees(m.normals, normal(m.vertices))
    assert ours.max() < normal_degrees
    measure = require("skimage.measure", "python3-skimage")
    verts, faces, normals, _ = measure.marching_cubes(volume, 0.0, spacing=spacing)
    verts = verts + np.asarray(origin)
    theirs = angle_degrees(-normals, normal(verts))  # their normals point down the gradient
    assert ours.mean() < 0.1 * theirs.mean() and ours.max() < theirs.max()


def test_axis_order_matches_scikit_image():
    # An ellipsoid longer along array axis 0: vertex column 0 spans the long axis.
    n = 40
    a = np.linspace(-1, 1, n)
    x, y, z = np.meshgrid(a, a, a, indexing="ij")
    volume = (x / 0.9) ** 2 + (y / 0.5) ** 2 + (z / 0.3) ** 2 - 1.0
    m = isopatch.mesh_volume(volume, spacing=(2 / (n - 1),) * 3, origin=(-1, -1, -1))
    extent = m.vertices.max(axis=0) - m.vertices.min(axis=0)
    np.testing.assert_allclose(extent, [1.8, 1.0, 0.6], atol=0.01)
    # Spacing scales the axes; an integer array works as well.
    m2 = isopatch.mesh_volume((volume * 100).astype(np.int32), spacing=(1, 2, 3), edge_length=2.0)
    e2 = m2.vertices.max(axis=0) - m2.vertices.min(axis=0)
    np.testing.assert_allclose(e2 / np.array([1, 2, 3]), extent / (2 / (n - 1)), rtol=0.05)


def test_inside_above_for_densities():
    # A mask (1 inside): with inside='above' the normals point out of the ball.
    n = 32
    a = np.linspace(-1, 1, n)
    x, y, z = np.meshgrid(a, a, a, indexing="ij")
    mask = (x * x + y * y + z * z < 0.5).astype(np.uint8)
    h = 2 / (n - 1)
    m = isopatch.mesh_volume(mask, level=0.5, spacing=(h, h, h), origin=(-1, -1, -1), inside="above")
    assert np.mean(np.sum(m.normals * m.vertices, axis=1) > 0) > 0.99
    below = isopatch.mesh_volume(mask, level=0.5, spacing=(h, h, h), origin=(-1, -1, -1))
    assert np.mean(np.sum(below.normals * below.vertices, axis=1) < 0) > 0.99
    with pytest.raises(isopatch.InputError, match="inside"):
        isopatch.mesh_volume(mask, level=0.5, inside="outside")


def test_level_and_errors():
    volume, spacing, origin = sampled(sphere, 24)
    inner = isopatch.mesh_volume(volume, level=-0.2, spacing=spacing, origin=origin)
    np.testing.assert_allclose(np.linalg.norm(inner.vertices, axis=1), 0.4, atol=5e-3)
    with pytest.raises(isopatch.NoSurfaceError, match="no sample of the volume crosses level 5"):
        isopatch.mesh_volume(volume, level=5.0)
    bad = volume.copy()
    bad[3, 4, 5] = np.nan
    with pytest.raises(isopatch.InputError, match=r"NaN at index \(3, 4, 5\)"):
        isopatch.mesh_volume(bad)
    with pytest.raises(isopatch.InputError, match="3-dimensional"):
        isopatch.mesh_volume(volume[0])
    with pytest.raises(isopatch.InputError, match="spacing"):
        isopatch.mesh_volume(volume, spacing=(1, 0, 1))
