"""Type checkers see the package's API: mypy (Debian's python3-mypy) passes on the package itself and on
a small typed client under --strict, and refuses a string option the package does not have (the string
options are Literal types; the compiled module has a stub, isopatch/_isopatch.pyi)."""

import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))


@pytest.fixture(scope="module")
def mypy(tmp_path_factory):
    """Runs Debian's mypy on the build tree's package (mypy reads MYPYPATH, not PYTHONPATH), with one
    cache for the module's runs in a temporary folder."""
    cache = str(tmp_path_factory.mktemp("mypy-cache"))
    environment = dict(os.environ, MYPYPATH=os.environ.get("PYTHONPATH", ""))

    def run(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", cache, *args],
                              capture_output=True, text=True, timeout=600, env=environment, cwd=HERE)
    return run


def test_the_package_type_checks(mypy):
    run = mypy("-p", "isopatch")
    assert run.returncode == 0, run.stdout + run.stderr


def test_a_typed_client_passes_strict_checking(mypy):
    run = mypy("--strict", os.path.join(HERE, "typed", "client.py"))
    assert run.returncode == 0, run.stdout + run.stderr


def test_an_option_the_package_does_not_have_is_refused_by_the_type_checker(mypy):
    run = mypy(os.path.join(HERE, "typed", "wrong_option.py"))
    assert run.returncode == 1, run.stdout + run.stderr
    assert 'Argument "quality" to "mesh" has incompatible type "Literal[\'fastest\']"' in run.stdout, run.stdout
