"""One version for the library, the tool and the package: isopatch.__version__ is the compiled module's
copy of project(isopatch VERSION ...) in the top CMakeLists.txt."""

import os
import pathlib
import re
import subprocess

import pytest

import isopatch

CLI = os.environ.get("ISOPATCH_CLI")
TOP_CMAKELISTS = pathlib.Path(__file__).resolve().parents[2] / "CMakeLists.txt"


def test_version_is_the_cmake_project_version():
    project = re.search(r"project\(isopatch\s+VERSION\s+([0-9.]+)", TOP_CMAKELISTS.read_text())
    assert project, "no project(isopatch VERSION ...) in the top CMakeLists.txt"
    assert isopatch.__version__ == project.group(1)
    assert re.fullmatch(r"\d+\.\d+\.\d+", isopatch.__version__)


@pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI (the tool built beside the package) is not set")
def test_version_is_the_tools_version():
    printed = subprocess.run([CLI, "--version"], capture_output=True, text=True, check=True).stdout
    assert printed.strip() == "isopatch " + isopatch.__version__
