"""setuptools driving CMake: the Python package `isopatch` as a wheel (pyproject.toml, docs/python.md).

`pip install --no-build-isolation .` and `python3 -m build --wheel --no-isolation` come here through
setuptools.build_meta. The package is built by the project's own CMake, exactly as for
`cmake --install <build> --component python` (scripts/run.sh), so the wheel holds the same files:

* version: project(isopatch VERSION x.y.z) of CMakeLists.txt, the one the compiled module reports as
  `isopatch.__version__` (checked against the build tree's generated <isopatch/version.hpp>);
* CMake build tree: $ISOPATCH_CMAKE_BUILD_DIR if set, else <source>/build/python-package. A tree that is
  already configured (CMakeCache.txt present) and named by $ISOPATCH_CMAKE_BUILD_DIR is never
  reconfigured: only `cmake --build DIR --target isopatch_python` (a no-op when current), so the tests
  package the test build's module instead of compiling the library again (tests/package/run_pip_test.py).
  Otherwise the tree is configured here for the module alone (Release, Ninja when installed, no tool,
  tests, benchmarks, examples, docs or install rules beyond the package's; $ISOPATCH_CMAKE_ARGS adds
  options) for this interpreter (-DPython_EXECUTABLE=sys.executable), and kept, so a second install
  recompiles nothing;
* files: the install component `python` (python/CMakeLists.txt: the module and ISOPATCH_PYTHON_SOURCES,
  i.e. the *.py files, py.typed and _isopatch.pyi) installed into a staging folder with DESTDIR and
  copied into the wheel, so that list stays the one list of the package's files;
* the wheel is a platform wheel (the distribution has an extension module, isopatch._isopatch), tagged
  for this interpreter (cp311-cp311-linux_x86_64 with Debian's python3.11);
* setuptools' own folders (build/, *.egg-info) go into <CMake tree>/setuptools, never into the source
  tree's build/ (scripts/run.sh's CMake tree) or beside setup.py.

Editable installs (`pip install -e .`) are not supported: use PYTHONPATH=<build>/python (docs/python.md).
"""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.egg_info import egg_info

SOURCE_DIR = Path(__file__).resolve().parent


def project_version() -> str:
    """The x.y.z of project(isopatch VERSION x.y.z ...) in the top CMakeLists.txt."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(\s*isopatch\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+)\b", text)
    if not match:
        raise RuntimeError("isopatch: no project(isopatch VERSION x.y.z ...) in CMakeLists.txt")
    return match.group(1)


def cmake_build_dir() -> Path:
    """The CMake build tree: $ISOPATCH_CMAKE_BUILD_DIR (relative: to the source folder), else build/python-package."""
    named = os.environ.get("ISOPATCH_CMAKE_BUILD_DIR")
    return (SOURCE_DIR / named).resolve() if named else SOURCE_DIR / "build" / "python-package"


def setuptools_dir() -> Path:
    """setuptools' build base and egg-info folder, inside the CMake tree."""
    return cmake_build_dir() / "setuptools"


def run(command: list[str], **kwargs: object) -> None:
    print("isopatch: " + shlex.join(command), flush=True)
    subprocess.run(command, check=True, **kwargs)  # type: ignore[call-overload]


class CMakeBuild(build_ext):
    """Builds isopatch._isopatch with CMake and copies the installed package into the wheel's tree."""

    def build_extension(self, ext: Extension) -> None:
        if self.inplace:
            raise RuntimeError("isopatch: editable installs are not supported; use PYTHONPATH=<build>/python "
                               "(docs/python.md)")
        tree = cmake_build_dir()
        if not ("ISOPATCH_CMAKE_BUILD_DIR" in os.environ and (tree / "CMakeCache.txt").exists()):
            self.configure(tree)
        build = ["cmake", "--build", str(tree), "--target", "isopatch_python"]
        if self.parallel:
            build += ["--parallel", str(self.parallel)]
        run(build)
        self.check_version(tree)

        # The install component `python` into a staging folder (DESTDIR: its destination is absolute,
        # ISOPATCH_PYTHON_INSTALL_DIR), then that isopatch/ folder as the wheel's.
        staging = Path(self.build_temp).resolve() / "cmake-install"
        shutil.rmtree(staging, ignore_errors=True)
        run(["cmake", "--install", str(tree), "--component", "python"],
            env={**os.environ, "DESTDIR": str(staging)})
        found = [init.parent for init in staging.rglob("isopatch/__init__.py")]
        if len(found) != 1:
            raise RuntimeError(f"isopatch: expected one isopatch/__init__.py under {staging}, found {found}")
        module = Path(self.get_ext_fullpath(ext.name))
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        if not (found[0] / module.name).exists():
            built = sorted(path.name for path in found[0].glob("_isopatch*"))
            raise RuntimeError(f"isopatch: {tree} built {built} but this interpreter ({sys.executable}) loads "
                               f"*{suffix}: configure that tree with -DPython_EXECUTABLE={sys.executable}")
        shutil.rmtree(module.parent, ignore_errors=True)  # nothing stale from an earlier build
        shutil.copytree(found[0], module.parent)

    def configure(self, tree: Path) -> None:
        command = ["cmake", "-S", str(SOURCE_DIR), "-B", str(tree)]
        if not (tree / "CMakeCache.txt").exists() and shutil.which("ninja"):
            command += ["-G", "Ninja"]
        if "CMAKE_BUILD_TYPE" not in os.environ.get("ISOPATCH_CMAKE_ARGS", ""):
            command.append("-DCMAKE_BUILD_TYPE=Release")
        command += [f"-D{option}=OFF" for option in ("ISOPATCH_BUILD_APPS", "ISOPATCH_BUILD_TESTS",
                                                     "ISOPATCH_BUILD_BENCH", "ISOPATCH_BUILD_EXAMPLES",
                                                     "ISOPATCH_BUILD_DOCS", "ISOPATCH_INSTALL",
                                                     "ISOPATCH_WERROR")]
        command += ["-DISOPATCH_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"]
        command += shlex.split(os.environ.get("ISOPATCH_CMAKE_ARGS", ""))
        run(command)

    @staticmethod
    def check_version(tree: Path) -> None:
        """The tree's library version (its generated version.hpp) must be this source's: the wheel's name says it."""
        header = tree / "generated" / "include" / "isopatch" / "version.hpp"
        match = re.search(r'kVersion = "([^"]*)"', header.read_text(encoding="utf-8")) if header.exists() else None
        if not match or match.group(1) != project_version():
            found = match.group(1) if match else f"no {header}"
            raise RuntimeError(f"isopatch: the CMake tree {tree} is version {found}, this source is "
                               f"{project_version()}")


class EggInfo(egg_info):
    """The .egg-info folder into the CMake tree (setuptools_dir()) unless a command chose one (dist_info)
    or an sdist is made (its manifest needs the folder inside the source tree: there, it is gitignored)."""

    def finalize_options(self) -> None:
        if self.egg_base is None and "sdist" not in self.distribution.commands:
            setuptools_dir().mkdir(parents=True, exist_ok=True)
            self.egg_base = str(setuptools_dir())
        super().finalize_options()


setup(
    version=project_version(),
    packages=[],  # setuptools finds and copies none: build_ext puts CMake's isopatch/ folder into the wheel
    license_files=["LICENSE", "THIRD_PARTY_NOTICES.md"],
    ext_modules=[Extension("isopatch._isopatch", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "egg_info": EggInfo},
    options={"build": {"build_base": str(setuptools_dir() / "build")}},
)
