"""Mesh files read by real clients. Open3D (Debian's python3-open3d 0.16) reads the PLY, OBJ, STL and GLB
that isopatch writes, from Python and from the command line, and finds each edge- and vertex-manifold,
orientable, free of self-intersections and watertight, with the mesh's vertices, its triangles in their
orientation and its enclosed volume, outward; meshio reads the PLY, OBJ and STL to the same. A broken mesh
fails the same checks. The slicer's view of STL and 3MF is test_print_clients.py's; the Khronos glTF
validator checks the GLB in tests/view."""

import os
import subprocess

import numpy as np
import pytest
from scipy.spatial import cKDTree  # Debian's python3-scipy, which python3-skimage brings

import isopatch

CLI = os.environ.get("ISOPATCH_CLI")
EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")

# Closed surfaces of genus 1 and 2, a cube with creases and corners and a composite surface, at edge
# lengths that keep each mesh at 2,000 to 6,500 triangles, where Open3D's self-intersection test (run by
# is_self_intersecting() and again by is_watertight()) takes about 0.1 s.
SURFACES = {
    "torus": dict(surface="torus", edge_length=0.1),
    "genus2": dict(surface="genus2"),
    "cube_with_creases": dict(surface="max(max(abs(x),abs(y)),abs(z))-1", box=((-1.5,) * 3, (1.5,) * 3),
                              edge_length=0.12),
    "rounded_box": dict(surface=os.path.join(EXAMPLES, "rounded_box.ipatch"), edge_length=0.12),
}

# How far a position read back may be from isopatch's double, in float32 spacings at that value (None:
# not at all). PLY holds doubles and OBJ the shortest decimals that read back as the same doubles; STL and
# GLB hold float32, within half a spacing. Open3D's OBJ reader (tinyobjloader) parses into float32 without
# rounding to the nearest: within one spacing. meshio reads OBJ as doubles, exactly. Open3D reads the
# GLB's positions as stored, without its node's turn from z-up to y-up, so they are isopatch's.
OPEN3D_ULPS = {"ply": None, "obj": 1.0, "stl": 0.5, "glb": 0.5}
# meshio 7 has no glTF reader (meshio.extension_to_filetypes has no .glb or .gltf), so it reads these three.
MESHIO_ULPS = {"ply": None, "obj": None, "stl": 0.5}


@pytest.fixture(scope="module")
def o3d():
    try:
        import open3d
    except ImportError:
        pytest.fail("open3d is missing (scripts/install-deps.sh installs python3-open3d)")
    open3d.utility.set_verbosity_level(open3d.utility.VerbosityLevel.Error)
    return open3d


@pytest.fixture(scope="module")
def meshio_lib():
    try:
        import meshio
    except ImportError:
        pytest.fail("meshio is missing (scripts/install-deps.sh installs python3-meshio)")
    return meshio


@pytest.fixture(scope="module")
def meshes():
    """The mesh of a name of SURFACES, made once for the module."""
    made = {}

    def get(name):
        if name not in made:
            made[name] = isopatch.mesh(**SURFACES[name])
        return made[name]

    return get


def written(meshes, tmp_path, name, extension):
    """The mesh of `name` and the file of it that Mesh.write made in `tmp_path`."""
    mesh = meshes(name)
    path = tmp_path / f"{name}.{extension}"
    mesh.write(str(path))
    return mesh, path


def signed_volume(vertices, faces) -> float:
    a, b, c = (np.asarray(vertices, dtype=np.float64)[np.asarray(faces)[:, k]] for k in range(3))
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def unit_normals(vertices, faces) -> np.ndarray:
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    n = np.cross(b - a, c - a)
    return n / np.linalg.norm(n, axis=1, keepdims=True)


def area_weighted_normals(mesh) -> np.ndarray:
    a, b, c = (mesh.vertices[mesh.faces[:, k]] for k in range(3))
    twice_area = np.cross(b - a, c - a)
    n = np.zeros_like(mesh.vertices)
    for k in range(3):
        np.add.at(n, mesh.faces[:, k], twice_area)
    return n / np.linalg.norm(n, axis=1, keepdims=True)


def oriented(faces) -> np.ndarray:
    """The triangles, each turned to start at its smallest index (a turn keeps its orientation, a swap of
    two corners would not), in sorted order."""
    faces = np.asarray(faces, dtype=np.int64)
    start = np.argmin(faces, axis=1)[:, None]
    turned = np.take_along_axis(faces, (start + np.arange(3)) % 3, axis=1)
    return turned[np.lexsort(turned.T[::-1])]


def expect_same_mesh(name, points, triangles, mesh, ulps) -> np.ndarray:
    """Asserts that the points and triangles a reader found in the file `name` are `mesh`: one point for
    each vertex, within `ulps` float32 spacings of it (None: equal), and the same triangles, each with the
    same orientation, in any order. Returns the index of each vertex's point."""
    points = np.asarray(points, dtype=np.float64)
    v = mesh.vertices
    assert (len(points), len(triangles)) == (len(v), len(mesh.faces)), f"{name}: vertex and triangle counts"
    _, match = cKDTree(points).query(v)
    assert len(np.unique(match)) == len(v), f"{name}: two vertices read as one point"
    error = np.abs(points[match] - v)
    if ulps is None:
        assert error.max() == 0.0, f"{name}: positions off by up to {error.max()}"
    else:
        bound = ulps * np.spacing(np.abs(v).astype(np.float32)).astype(np.float64)
        assert (error <= bound).all(), f"{name}: positions beyond {ulps} float32 spacings"
    assert np.array_equal(oriented(triangles), oriented(match[mesh.faces])), \
        f"{name}: other triangles, or triangles turned over"
    return match


def expect_closed_manifold(o3d, path, mesh, ulps) -> None:
    """Asserts that Open3D reads the file `path` as `mesh` (expect_same_mesh), a closed, manifold,
    orientable mesh without self-intersections whose triangles face outward around the mesh's volume."""
    read = o3d.io.read_triangle_mesh(str(path))
    name = path.name
    if path.suffix == ".stl":
        # STL stores a triangle soup, three corners of their own per triangle, and Open3D's reader leaves
        # them apart (giving each its facet's normal, which must be the triangle's own by the right-hand
        # rule, to float32). Like any reader of STL, merge the corners at equal positions
        # (remove_duplicated_vertices() merges exactly equal coordinates): that must give back isopatch's
        # vertices, no fewer.
        triangles = np.asarray(read.triangles)
        np.testing.assert_allclose(np.asarray(read.vertex_normals)[triangles[:, 0]],
                                   unit_normals(np.asarray(read.vertices), triangles), atol=1e-5,
                                   err_msg=f"{name}: facet normals")
        read = read.remove_duplicated_vertices()
    assert (len(read.vertices), len(read.triangles)) == (len(mesh.vertices), len(mesh.faces)), \
        f"{name}: Open3D reads {len(read.vertices)} vertices and {len(read.triangles)} triangles"
    # Self-intersections before watertightness: Open3D's is_watertight() includes the self-intersection
    # test, and this order tells which one failed.
    assert read.is_edge_manifold(), f"{name}: Open3D finds an edge that is not manifold"
    assert read.is_vertex_manifold(), f"{name}: Open3D finds a vertex that is not manifold"
    assert read.is_orientable(), f"{name}: Open3D finds the mesh not orientable"
    assert not read.is_self_intersecting(), f"{name}: Open3D finds the mesh self-intersecting"
    assert read.is_watertight(), f"{name}: Open3D finds the mesh not watertight"
    points, triangles = np.asarray(read.vertices), np.asarray(read.triangles)
    match = expect_same_mesh(name, points, triangles, mesh, ulps)
    if path.suffix == ".glb":  # its NORMAL: the unit area-weighted normals of the triangles (docs/viewer.md)
        np.testing.assert_allclose(np.asarray(read.vertex_normals)[match], area_weighted_normals(mesh),
                                   atol=1e-6, err_msg=f"{name}: vertex normals")
    volume = signed_volume(points, triangles)
    assert volume > 0, f"{name}: the triangles face inward (enclosed volume {volume})"
    rel = 1e-12 if ulps is None else 1e-6  # float32 positions move the volume by a few 1e-8 of it
    assert volume == pytest.approx(signed_volume(mesh.vertices, mesh.faces), rel=rel), name
    assert read.get_volume() == pytest.approx(volume, rel=1e-9), name  # Open3D's own sum, unsigned


@pytest.mark.parametrize("name", SURFACES)
@pytest.mark.parametrize("extension", list(OPEN3D_ULPS))
def test_open3d_reads_a_closed_manifold_of_the_meshs_volume(o3d, meshes, tmp_path, name, extension):
    m, path = written(meshes, tmp_path, name, extension)
    expect_closed_manifold(o3d, path, m, OPEN3D_ULPS[extension])


@pytest.mark.parametrize("name", SURFACES)
@pytest.mark.parametrize("extension", list(MESHIO_ULPS))
def test_meshio_reads_the_mesh(meshio_lib, meshes, tmp_path, name, extension):
    m, path = written(meshes, tmp_path, name, extension)
    back = meshio_lib.read(str(path))
    assert list(back.cells_dict) == ["triangle"], path.name
    # meshio's STL reader merges the corners at equal positions itself.
    expect_same_mesh(path.name, back.points, back.cells_dict["triangle"], m, MESHIO_ULPS[extension])


@pytest.mark.skipif(CLI is None, reason="the command-line tool is not built")
@pytest.mark.parametrize("extension", list(OPEN3D_ULPS))
def test_the_command_lines_files_of_a_composite_surface(o3d, meshio_lib, meshes, tmp_path, extension):
    spec = SURFACES["rounded_box"]
    path = tmp_path / f"rounded_box.{extension}"
    subprocess.run([CLI, "mesh", spec["surface"], "--edge-length", repr(spec["edge_length"]), "-o", str(path),
                    "-q"], check=True, timeout=300)
    # The tool's mesh of a composite surface is the package's (docs/python.md), so its files are held to
    # the package's mesh.
    m = meshes("rounded_box")
    expect_closed_manifold(o3d, path, m, OPEN3D_ULPS[extension])
    if extension in MESHIO_ULPS:
        back = meshio_lib.read(str(path))
        expect_same_mesh(path.name, back.points, back.cells_dict["triangle"], m, MESHIO_ULPS[extension])


def broken(m, how):
    vertices, faces = m.vertices.copy(), m.faces.copy()
    if how == "face_removed":
        faces = faces[1:]
    elif how == "turned_inward":
        faces = faces[:, ::-1].copy()
    else:  # "pushed_through": a vertex of the torus's outer rim moved into the tube across the hole
        vertices[np.argmax(vertices[:, 0])] = (-1.0, 0.0, 0.0)
    return isopatch.Mesh.from_arrays(vertices, faces, "torus")


@pytest.mark.parametrize("how,message", [("face_removed", "not watertight"), ("turned_inward", "face inward"),
                                         ("pushed_through", "self-intersecting")])
def test_the_checks_catch_a_broken_mesh(o3d, meshes, tmp_path, how, message):
    """The assertions are live: each breakage of the torus, written by isopatch as it stands, fails them."""
    bad = broken(meshes("torus"), how)
    path = tmp_path / f"{how}.ply"
    bad.write(str(path))
    with pytest.raises(AssertionError, match=message):
        expect_closed_manifold(o3d, path, bad, OPEN3D_ULPS["ply"])


def test_the_open3d_line_of_the_docs(o3d, meshes):
    """docs/python.md's Open3D constructor takes the arrays as they are (int64 faces included)."""
    m = meshes("torus")
    vertices, faces = o3d.utility.Vector3dVector(m.vertices), o3d.utility.Vector3iVector(m.faces)
    built = o3d.geometry.TriangleMesh(vertices, faces)
    np.testing.assert_array_equal(np.asarray(built.vertices), m.vertices)
    np.testing.assert_array_equal(np.asarray(built.triangles), m.faces)
    assert built.is_watertight()
