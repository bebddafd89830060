"""Every library error as a Python exception with the library's message (the command line's, too)."""

import os
import subprocess

import numpy as np
import pytest

import isopatch

CLI = os.environ.get("ISOPATCH_CLI")


def cli_error(*args):
    """The command line's stderr and exit code for `isopatch mesh ARGS -o out.ply`."""
    r = subprocess.run([CLI, "mesh", *args, "-o", os.devnull + ".ply", "-q"], capture_output=True, text=True)
    return r.stderr, r.returncode


def test_parse_error_keeps_its_column(unit_box):
    with pytest.raises(isopatch.ParseError) as info:
        isopatch.mesh("x^2 + y^2 + * z", box=unit_box)
    e = info.value
    assert e.column == 13 and e.line == 1
    assert "column 13" in str(e) and "^" in e.excerpt
    assert isinstance(e, ValueError) and isinstance(e, isopatch.Error)
    if CLI:
        stderr, code = cli_error("x^2 + y^2 + * z", "--box", "-1,-1,-1,1,1,1")
        assert str(e) in stderr and code == 5


def test_unknown_surface_suggests(unit_box):
    with pytest.raises(isopatch.UnknownSurfaceError, match="did you mean 'torus'"):
        isopatch.mesh("tours")


def test_setting_errors_name_the_setting(unit_box):
    with pytest.raises(isopatch.SettingError) as info:
        isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, edge_length=-1.0)
    assert info.value.setting == "edge_length"
    with pytest.raises(isopatch.SettingError) as info:
        isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, quality="best")
    assert info.value.setting == "quality"
    with pytest.raises(isopatch.SettingError) as info:
        isopatch.mesh("x^2+y^2+z^2-1", box=((1, 1, 1), (0, 0, 0)))
    assert info.value.setting == "box"
    with pytest.raises(isopatch.InputError, match="needs a box"):
        isopatch.mesh("x^2+y^2+z^2-1")
    with pytest.raises(isopatch.SettingError, match="edge_length has the wrong type") as info:
        isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, edge_length="fine")
    assert info.value.setting == "edge_length"


def test_no_surface_and_limits(unit_box):
    with pytest.raises(isopatch.NoSurfaceError):
        isopatch.mesh("x^2+y^2+z^2+1", box=unit_box)
    with pytest.raises(isopatch.LimitError) as info:
        isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, max_vertices=100)
    assert info.value.setting == "max_vertices"
    with pytest.raises(isopatch.NoSurfaceError, match="does not change sign"):
        isopatch.mesh(lambda p: np.ones(len(p)), box=unit_box)


def test_callable_errors(unit_box):
    def nan_at_origin(p):
        v = np.sum(p * p, axis=1) - 1.0
        v[np.all(np.abs(p) < 0.05, axis=1)] = np.nan
        return v

    with pytest.raises(isopatch.EvaluationError, match="f is NaN at"):
        isopatch.mesh(nan_at_origin, box=unit_box, samples=48)
    with pytest.raises(isopatch.InputError, match=r"shape \(7, 2\)"):
        isopatch.mesh(lambda p: np.zeros((7, 2)), box=unit_box)

    def broken(p):
        raise ZeroDivisionError("from the user's function")

    with pytest.raises(ZeroDivisionError, match="from the user's function"):
        isopatch.mesh(broken, box=unit_box)
    with pytest.raises(isopatch.InputError):
        isopatch.mesh(42, box=unit_box)
