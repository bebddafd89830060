"""isopatch.mesh with formulas and catalogue names: arrays, fields, statistics, determinism."""

import numpy as np

import isopatch


def test_formula_sphere_arrays(unit_box):
    m = isopatch.mesh("x^2+y^2+z^2-1", box=unit_box)
    v, f, n = m.vertices, m.faces, m.normals
    assert v.dtype == np.float64 and v.ndim == 2 and v.shape[1] == 3 and len(v) > 1000
    assert f.dtype == np.int64 and f.shape[1] == 3 and f.min() >= 0 and f.max() < len(v)
    assert n.shape == v.shape
    np.testing.assert_allclose(np.linalg.norm(v, axis=1), 1.0, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-12)
    assert np.all(np.sum(n * v, axis=1) > 0.999)  # outward, along grad f
    # Faces counter-clockwise seen from outside: face normals along the vertex normals.
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    assert np.all(np.sum(np.cross(b - a, c - a) * (a + b + c), axis=1) > 0)


def test_catalogue_name_uses_its_own_box():
    assert "torus" in isopatch.catalogue()
    m = isopatch.mesh("torus", quality="preview")
    report = m.analyze()
    assert report["topology"]["watertight"] and report["topology"]["genus"] == 1


def test_fields_and_stats(unit_box):
    m = isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, edge_length=0.1)
    fields = m.fields
    for name in ("mean_curvature", "mean_curvature_exact", "gaussian_curvature", "gaussian_curvature_exact",
                 "distance"):
        assert fields[name].shape == (len(m.vertices),) and fields[name].dtype == np.float64
    np.testing.assert_allclose(fields["mean_curvature_exact"], 1.0, rtol=1e-9)
    np.testing.assert_allclose(fields["mean_curvature"], 1.0, atol=0.05)
    assert np.abs(fields["distance"]).max() < 1e-9
    stats = m.stats
    assert stats["mesh"]["vertices"] == len(m.vertices)
    assert stats["mesh"]["triangles"] == len(m.faces)
    assert stats["mesh"]["seconds"] > 0
    # The whole call, from isopatch.mesh's start to its return, with its stages inside it.
    seconds = dict(stats["seconds"])
    total = seconds.pop("total")
    assert stats["mesh"]["seconds"] <= total and sum(seconds.values()) <= total
    assert "feature_search" in seconds and "size_estimate" in seconds


def test_settings_pass_through(unit_box):
    coarse = isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, edge_length=0.2)
    fine = isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, edge_length=0.1)
    assert 3 < len(fine.vertices) / len(coarse.vertices) < 5  # about (0.2 / 0.1)^2
    mc = isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, method="mc", grid=20)
    assert mc.stats["marching_cubes"]["cells"] > 0
    params = isopatch.mesh("r = 0.5; x^2+y^2+z^2-r^2", box=unit_box, params={"r": 0.8}, edge_length=0.1)
    np.testing.assert_allclose(np.linalg.norm(params.vertices, axis=1), 0.8, atol=1e-9)


def test_same_input_same_arrays(unit_box):
    a = isopatch.mesh("x^4+y^4+z^4-1", box=unit_box, edge_length=0.1, threads=1)
    b = isopatch.mesh("x^4+y^4+z^4-1", box=unit_box, edge_length=0.1, threads=2)
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.faces, b.faces)


def test_refine_levels_and_their_statistics():
    # The automatic level refines a gently curved surface; refine=1 is the single-level pipeline; an
    # explicit level is used as given; out of range is a SettingError naming "refine".
    auto = isopatch.mesh("torus", edge_length=0.03)
    assert auto.stats["refine"]["level"] >= 2
    assert auto.stats["refine"]["base_vertices"] * 4 < len(auto.vertices)
    report = auto.analyze()
    assert report["topology"]["watertight"] and report["topology"]["genus"] == 1
    assert report["valence"]["share_6"] >= 0.97
    single = isopatch.mesh("torus", edge_length=0.03, refine=1)
    assert "refine" not in single.stats
    fixed = isopatch.mesh("torus", edge_length=0.03, refine=3)
    assert fixed.stats["refine"]["level"] == 3
    try:
        isopatch.mesh("torus", refine=17)
    except isopatch.SettingError as e:
        assert e.setting == "refine"
    else:
        raise AssertionError("refine=17 was accepted")


def test_an_absurd_size_is_refused_before_any_work():
    try:
        isopatch.mesh("sphere", edge_length=1e-5, max_vertices=10_000_000)
    except isopatch.LimitError as e:
        assert e.setting == "max_vertices" and "about" in str(e)
    else:
        raise AssertionError("no LimitError")


def test_sizes_refined_at_a_narrow_cut_unless_uniform():
    # Schwarz P passes 0.003 from the box edge x = 1.937, z = 2.271 without crossing it: a strip of
    # surface that narrow between two box faces. By default sizes shrink there (and the statistics say
    # where and how many vertices it added); uniform=True keeps one size and leaves a sliver.
    box = ((-2.128, -1.742, -1.814), (1.937, 2.097, 2.271))
    local = isopatch.mesh("cos(x)+cos(y)+cos(z)", box=box)
    sizes = local.stats["local_sizes"]
    assert sizes["sources"] > 0 and sizes["added_vertices"] > 0
    assert sizes["smallest_size"] < 0.5 * 4.085 / 64
    assert local.analyze()["shape"]["min_angle_degrees"]["min"] >= 20.0
    uniform = isopatch.mesh("cos(x)+cos(y)+cos(z)", box=box, uniform=True)
    assert "local_sizes" not in uniform.stats
    assert uniform.analyze()["shape"]["min_angle_degrees"]["min"] < 10.0


def test_sizes_follow_a_rim_thinner_than_an_edge_unless_uniform():
    # An ellipsoid with semi-axes 4, 1, 0.2: its rim turns with radius 0.01, a thirteenth of the default
    # edge. By default sizes shrink along the rim (the statistics count those points and where they are)
    # and the mean curvature there is resolved; with uniform=True one row of triangles spans the rim.
    f = "x^2/16+y^2+z^2/0.04-1"
    box = ((-4.2, -4.2, -4.2), (4.2, 4.2, 4.2))
    local = isopatch.mesh(f, box=box)
    sizes = local.stats["local_sizes"]
    assert sizes["curvature_sources"] > 0 and sizes["sources"] == 0
    assert sizes["extent_hi_z"] < 0.2 and sizes["extent_hi_x"] <= 4.0 + 1e-9
    report = local.analyze()
    assert report["shape"]["min_angle_degrees"]["min"] >= 20.0
    assert report["accuracy"]["mean_curvature"]["nrms"] <= 0.1
    uniform = isopatch.mesh(f, box=box, uniform=True)
    assert "local_sizes" not in uniform.stats
    assert uniform.analyze()["accuracy"]["mean_curvature"]["nrms"] > 3 * report["accuracy"]["mean_curvature"]["nrms"]
