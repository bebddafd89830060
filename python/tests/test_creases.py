"""isopatch.mesh on CSG formulas: meshed along their exact creases and corners by default, as smooth
surfaces with creases='off', shapes the crease paths cannot follow rounded with a warning (refused with
creases='exact'), and CreaseError for shapes no mesh can follow."""

import os
import re
import subprocess

import numpy as np
import pytest

import isopatch

CLI = os.environ.get("ISOPATCH_CLI")

CUBE = "max(max(abs(x),abs(y)),abs(z))-1"
BOX = ((-1.5, -1.5, -1.5), (1.5, 1.5, 1.5))


def test_a_cube_keeps_its_edges_and_corners():
    m = isopatch.mesh(CUBE, box=BOX)
    v = m.vertices
    # Every corner is a vertex; every vertex is on the cube, those near an edge exactly on it.
    for corner in np.array(np.meshgrid([-1, 1], [-1, 1], [-1, 1])).T.reshape(-1, 3):
        assert np.min(np.linalg.norm(v - corner, axis=1)) < 1e-12
    np.testing.assert_allclose(np.max(np.abs(v), axis=1), 1.0, atol=1e-12)
    second = np.sort(np.abs(v), axis=1)[:, 1]
    near_edge = second > 1 - 1e-3
    assert near_edge.sum() > 200
    np.testing.assert_allclose(second[near_edge], 1.0, atol=1e-12)
    creases = m.stats["creases"]
    assert (creases["faces"], creases["creases"], creases["corners"]) == (6, 12, 8)
    # Certified by interval arithmetic: every cell where two faces may meet is explained.
    assert creases["interval_cells"] > 0 and creases["uncertain_cells"] == 0
    assert m.stats["warnings"]["uncertain_crease_cells"] == 0
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["euler_characteristic"] == 2
    assert report["shape"]["min_angle_degrees"]["min"] >= 25.0


def test_creases_off_rounds_them_as_before():
    m = isopatch.mesh(CUBE, box=BOX, creases="off")
    assert "creases" not in m.stats
    assert np.min(np.linalg.norm(m.vertices - np.array([1.0, 1.0, 1.0]), axis=1)) > 1e-6


def test_bad_creases_setting_and_bad_shapes():
    with pytest.raises(isopatch.SettingError) as e:
        isopatch.mesh(CUBE, box=BOX, creases="sharp")
    assert e.value.setting == "creases"
    # Two boxes touching along an edge: not a 2-manifold.
    touching = "min(max(max(abs(x),abs(y)),abs(z))-1,max(max(abs(x-2),abs(y-2)),abs(z))-1)"
    with pytest.raises(isopatch.CreaseError) as crease:
        isopatch.mesh(touching, box=((-1.5, -1.5, -1.5), (3.5, 3.5, 1.5)))
    # The way out in Python's words (the command line names its flags).
    assert 'creases="off"' in str(crease.value) and "--" not in str(crease.value)


@pytest.mark.skipif(CLI is None, reason="the command-line tool is not built")
def test_the_command_line_names_its_own_flags_in_a_crease_error(tmp_path):
    touching = "min(max(max(abs(x),abs(y)),abs(z))-1,max(max(abs(x-2),abs(y-2)),abs(z))-1)"
    run = subprocess.run([CLI, "mesh", touching, "--box", "-1.5,-1.5,-1.5,3.5,3.5,1.5", "-o",
                          str(tmp_path / "m.ply")], capture_output=True, text=True, timeout=120)
    assert run.returncode == 11 and "--creases off" in run.stderr and 'creases="off"' not in run.stderr


GYROID = "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)"


@pytest.mark.parametrize("lattice", [GYROID, f"abs({GYROID})-0.4"], ids=["solid", "sheet"])
def test_a_gyroid_capped_by_its_box_is_one_closed_part_with_planar_caps(lattice):
    # docs/lattices.md: the cut surface closed by planar caps, the box's corners on the gyroid.
    part = f"max({lattice},max(max(abs(x),abs(y)),abs(z))-pi)"
    m = isopatch.mesh(part, box=((-3.3,) * 3, (3.3,) * 3), edge_length=0.2)
    assert m.stats["creases"]["caps"] == 6 and m.stats["creases"]["crease_vertices"] > 0
    v = m.vertices
    assert np.max(np.abs(v)) <= np.pi + 1e-12
    on_cap = np.isclose(np.max(np.abs(v), axis=1), np.pi, rtol=0, atol=1e-12)
    assert on_cap.sum() > 100
    x, y, z = v.T
    values = np.maximum(np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
                        if lattice == GYROID else
                        np.abs(np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)) - 0.4,
                        np.max(np.abs(v), axis=1) - np.pi)
    assert np.max(np.abs(values)) < 1e-9  # every vertex on the part's surface
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["outward_oriented"]
    assert report["valence"]["share_6"] >= 0.9


def test_a_gyroid_cut_by_a_ball_is_one_closed_part_along_its_crease():
    # docs/lattices.md: the gyroid and the ball meshed whole, trimmed to each other, joined at the crease.
    m = isopatch.mesh(f"max({GYROID},x^2+y^2+z^2-9)", box=((-3.4,) * 3, (3.4,) * 3), edge_length=0.1)
    assert m.stats["creases"]["faces"] == 2 and m.stats["creases"]["crease_vertices"] > 100
    x, y, z = m.vertices.T
    g = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
    ball = x * x + y * y + z * z - 9
    assert np.max(np.abs(np.maximum(g, ball))) < 1e-9  # every vertex on the part's surface
    on_both = (np.abs(g) < 1e-9) & (np.abs(ball) < 1e-9)
    assert on_both.sum() == m.stats["creases"]["crease_vertices"]
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["outward_oriented"]
    assert report["valence"]["share_6"] >= 0.9
    assert report["shape"]["min_angle_degrees"]["min"] >= 25.0


def test_a_frame_keeps_the_creases_of_a_polyhedron_and_of_any_csg_shape():
    m = isopatch.mesh(CUBE, box=BOX, frame=(30, 20, 10))
    assert m.stats["creases"]["caps"] == 6
    second = np.sort(np.abs(m.vertices), axis=1)[:, 1]
    assert (second > 1 - 1e-12).sum() > 100  # the cube's edges, exactly
    # A union (no capped solid): the crease path has no partition to turn, the mesh is the one without it.
    union = "min(max(max(abs(x),abs(y)),abs(z))-1,max(max(abs(x-1.5),abs(y)),abs(z-0.3))-0.5)"
    box = ((-1.5, -1.5, -1.5), (2.5, 1.5, 1.5))
    turned = isopatch.mesh(union, box=box, frame=(30, 20, 10), edge_length=0.15)
    plain = isopatch.mesh(union, box=box, edge_length=0.15)
    assert turned.stats["creases"]["creases"] > 12
    assert "creases_in_partition" not in turned.stats["warnings"]
    assert np.array_equal(turned.vertices, plain.vertices) and np.array_equal(turned.faces, plain.faces)


def test_a_region_cuts_any_csg_shape_open_along_its_creases():
    # A sphere with a hole (no capped solid), cut at x = 0.3: the hole's rims exact, the cut on the plane.
    m = isopatch.mesh("max(x^2+y^2+z^2-1,0.25-x^2-y^2)", box=((-1.2,) * 3, (1.2,) * 3), region="1,0,0,-0.3")
    assert m.stats["creases"]["cut_planes"] == 1
    x, y, z = m.vertices.T
    assert np.max(x) == 0.3
    rim = (np.abs(x * x + y * y + z * z - 1) < 1e-9) & (np.abs(0.25 - x * x - y * y) < 1e-9)
    assert rim.sum() > 40
    report = m.analyze()
    assert report["topology"]["boundary_edges"] > 0 and report["topology"]["manifold"]
    assert report["shape"]["min_angle_degrees"]["min"] >= 25.0


def test_a_region_half_space_cuts_a_cube_open_along_its_creases():
    m = isopatch.mesh(CUBE, box=BOX, region="1,0,0,-0.5", edge_length=0.1)
    assert m.stats["creases"]["caps"] == 5
    assert np.max(m.vertices[:, 0]) <= 0.5 + 1e-12
    report = m.analyze()
    assert not report["topology"]["watertight"] and report["topology"]["boundary_edges"] > 0
    assert report["shape"]["min_angle_degrees"]["min"] >= 25.0


def test_a_mesh_that_crosses_itself_says_so():
    # Two thin tori intersected, united with a ball and an ellipsoid (random model 95 of
    # docs/robustness.md): where the tori's thin lens meets the others, triangles of the mesh cross. Every
    # mesh isopatch.mesh returns has had the exact check: the count is in its warnings, the same as
    # analyze() finds; a clean mesh has no such warning.
    formula = ("min(max((sqrt((x-(0.34))^2+(y-(0.437))^2)-0.511)^2+(z-(0.536))^2-0.096721,"
               "(sqrt((x-(-0.498))^2+(y-(-0.268))^2)-0.727)^2+(z-(-0.367))^2-0.065536),"
               "min((x-(-0.168))^2+(y-(0.292))^2+(z-(-0.136))^2-0.242064,"
               "((x-(-0.13))/0.678)^2+((y-(-0.192))/0.578)^2+((z-(-0.385))/0.861)^2-1))")
    m = isopatch.mesh(formula, box=((-1.525, -1.606, -1.697), (1.574, 1.606, 1.618)), edge_length=0.1,
                      threads=2)
    pairs = m.analyze(surface=False)["self_intersections"]["pairs"]
    assert pairs > 0
    assert m.stats["warnings"]["self_intersecting_pairs"] == pairs
    clean = isopatch.mesh("sphere", edge_length=0.2)
    assert "self_intersecting_pairs" not in clean.stats.get("warnings", {})


def test_a_gyroid_in_a_capped_cylinder_is_one_closed_part_along_its_creases():
    # docs/lattices.md: the gyroid and the cylinder meshed as two solids in the planes' box, open on its
    # faces, closed by the planes' caps. The gyroid is odd: its solid is half the cylinder.
    m = isopatch.mesh(f"max({GYROID},max(x^2+y^2-25,abs(z)-5))", box=((-6,) * 3, (6,) * 3), edge_length=0.2)
    assert m.stats["creases"]["faces"] == 4 and m.stats["creases"]["caps"] == 2
    x, y, z = m.vertices.T
    g = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
    cylinder = x * x + y * y - 25
    plane = np.abs(z) - 5
    assert np.max(np.abs(np.maximum(np.maximum(g, cylinder), plane))) < 1e-9
    on_two = ((np.abs(g) < 1e-9).astype(int) + (np.abs(cylinder) < 1e-9) + (np.abs(plane) < 1e-12)) >= 2
    assert on_two.sum() > 300
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["outward_oriented"]
    assert report["self_intersections"]["pairs"] == 0
    assert report["valence"]["share_6"] >= 0.9
    a, b, c = (m.vertices[m.faces[:, k]] for k in range(3))
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0
    assert abs(volume / (0.5 * np.pi * 25 * 10) - 1) < 2e-3


@pytest.mark.parametrize("insert", ["solid", "void"])
def test_a_gyroid_with_a_solid_ball_or_a_void_capped_by_its_box_is_one_closed_part_along_its_creases(insert):
    # docs/lattices.md "Unions and voids": min(g, ball) read as -max(-g, -ball), max(g, -ball) with the
    # ball's sphere closed around an unbounded solid. The gyroid is odd and the box and ball symmetric: the
    # part holds half the box plus (solid) or minus (void) half the ball.
    ball = "x^2+y^2+z^2-4"
    solids = f"min({GYROID},{ball})" if insert == "solid" else f"max({GYROID},-({ball}))"
    m = isopatch.mesh(f"max({solids},max(max(abs(x),abs(y)),abs(z))-5)", box=((-5.4,) * 3, (5.4,) * 3),
                      edge_length=0.25)
    assert "creases_rounded" not in m.stats["warnings"]
    assert m.stats["creases"]["caps"] == 6 and m.stats["creases"]["crease_vertices"] > 100
    x, y, z = m.vertices.T
    g = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
    b = x * x + y * y + z * z - 4
    on_ball_and_gyroid = (np.abs(g) < 1e-9) & (np.abs(b) < 1e-9)
    assert on_ball_and_gyroid.sum() > 50  # the crease, exact on both
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["outward_oriented"]
    assert report["self_intersections"]["pairs"] == 0
    assert report["valence"]["share_6"] >= 0.9
    assert report["shape"]["min_angle_degrees"]["min"] >= 25.0
    a, bb, c = (m.vertices[m.faces[:, k]] for k in range(3))
    volume = np.einsum("ij,ij->i", a, np.cross(bb, c)).sum() / 6.0
    half_ball = 0.5 * 4.0 / 3.0 * np.pi * 8.0
    assert abs(volume / (500.0 + (half_ball if insert == "solid" else -half_ball)) - 1) < 2e-3


def test_a_lattice_sheet_inside_a_spherical_skin_is_meshed_along_its_creases_in_any_frame():
    # docs/lattices.md "Skins": max(outer, min(lattice, -inner)), the outer sphere apart from the rest, each
    # meshed by its own path; a frame keeps the creases.
    r = "sqrt(x^2+y^2+z^2)"
    formula = f"max({r}-5,min(abs({GYROID})-0.3,4.5-{r}))"
    box = ((-5.4,) * 3, (5.4,) * 3)
    m = isopatch.mesh(formula, box=box, edge_length=0.25)
    assert "creases_rounded" not in m.stats["warnings"]
    x, y, z = m.vertices.T
    g = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
    radius = np.sqrt(x * x + y * y + z * z)
    crease = (np.abs(np.abs(g) - 0.3) < 1e-9) & (np.abs(radius - 4.5) < 1e-9)
    assert crease.sum() > 100 and crease.sum() <= m.stats["creases"]["crease_vertices"]
    assert np.sum(np.abs(radius - 5) < 1e-9) > 1000  # the skin's outer sphere
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["outward_oriented"]
    assert report["self_intersections"]["pairs"] == 0
    assert report["valence"]["share_6"] >= 0.9
    assert report["shape"]["min_angle_degrees"]["min"] >= 25.0
    turned = isopatch.mesh(formula, box=box, edge_length=0.25, frame=(30, 20, 10))
    assert "creases_rounded" not in turned.stats["warnings"]
    ratio = turned.stats["creases"]["crease_vertices"] / m.stats["creases"]["crease_vertices"]
    assert abs(ratio - 1) < 0.05


def test_a_gyroid_in_a_cylinder_the_box_cuts_is_open_exactly_on_the_box_with_its_crease():
    # docs/lattices.md "Cut open by the box": both solids meshed in the box, the crease in arcs from the box
    # to the box, the boundary exactly on the box's faces.
    lo, hi = (-6.6, -6.6, -6.6), (6.6, 6.6, 6.6)
    m = isopatch.mesh(f"max({GYROID},x^2+y^2-25)", box=(lo, hi), edge_length=0.2)
    assert m.stats["creases"]["faces"] == 2 and "creases_leave_box" not in m.stats["warnings"]
    x, y, z = m.vertices.T
    g = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
    cylinder = x * x + y * y - 25
    assert np.max(np.abs(np.maximum(g, cylinder))) < 1e-9
    crease = (np.abs(g) < 1e-9) & (np.abs(cylinder) < 1e-9)
    assert crease.sum() == m.stats["creases"]["crease_vertices"]
    assert np.sum(crease & (np.abs(z) == 6.6)) >= 2  # the arcs' ends, exactly on the box
    report = m.analyze()
    topology = report["topology"]
    assert topology["boundary_edges"] > 0 and topology["manifold"] and topology["consistently_oriented"]
    assert report["self_intersections"]["pairs"] == 0
    edges = np.sort(np.concatenate([m.faces[:, [0, 1]], m.faces[:, [1, 2]], m.faces[:, [2, 0]]]), axis=1)
    unique, count = np.unique(edges, axis=0, return_counts=True)
    boundary = m.vertices[np.unique(unique[count == 1])]
    assert np.all(np.min(np.abs(np.concatenate([boundary - lo, boundary - hi], axis=1)), axis=1) == 0.0)
    assert report["shape"]["min_angle_degrees"]["min"] >= 20.0


def test_creases_the_paths_cannot_follow_are_rounded_with_a_warning_or_refused_when_exact():
    # A gyroid in a capped cylinder cut by a tilted plane is neither a lattice capped by planes alone, nor
    # one cut by one curved solid, nor two solids capped by planes across the axes: the general crease path
    # cannot cut its face into pieces. By default the shape is meshed as a smooth surface (closed, its
    # creases rounded) and says so; creases="exact" refuses it, naming the place, the forms that are meshed
    # along their creases, a smaller edge and creases off, in Python's words.
    capped = f"max({GYROID},max(x^2+y^2-25,abs(z)-5),0.6*x+0.8*z-4)"
    box = ((-6,) * 3, (6,) * 3)
    m = isopatch.mesh(capped, box=box, edge_length=0.2)
    assert m.stats["warnings"]["creases_rounded"] == 1 and "creases" not in m.stats
    assert m.analyze(surface=False)["topology"]["watertight"]
    with pytest.raises(isopatch.CreaseError) as crease:
        isopatch.mesh(capped, box=box, edge_length=0.2, creases="exact")
    message = str(crease.value)
    assert re.search(r"\(-?[0-9.]+, -?[0-9.]+, -?[0-9.]+\)", message) and "docs/lattices.md" in message
    assert "edge_length=0.1" in message and 'creases="off"' in message and "--" not in message
    # A shape no mesh can follow is refused whatever creases asks (solids touching along an edge).
    touching = "min(max(max(abs(x),abs(y)),abs(z))-1,max(max(abs(x-2),abs(y-2)),abs(z))-1)"
    with pytest.raises(isopatch.CreaseError):
        isopatch.mesh(touching, box=((-1.5, -1.5, -1.5), (3.5, 3.5, 1.5)))
