"""The pip package (pyproject.toml, setup.py): test package.pip (tests/package/CMakeLists.txt).

With ISOPATCH_CMAKE_BUILD_DIR naming the test build tree (setup.py then only runs
`cmake --build TREE --target isopatch_python`, a no-op, and packages that tree's module), it

1. builds a wheel: python3 -m build --wheel --no-isolation --outdir WORK/dist SOURCE;
2. installs the source: pip install --no-build-isolation --no-deps --no-index --target WORK/site SOURCE;
3. installs the wheel: pip install --no-deps --no-index --target WORK/site2 WHEEL;

checks the wheel (a cp311 platform wheel named with the tool's version, holding _isopatch*.so, the .vdb
plugin isopatch_openvdb.so, py.typed, _isopatch.pyi and every python/isopatch/*.py, nothing else in isopatch/; numpy required, extra
"distributed"), then in a fresh interpreter per target (PYTHONPATH=target, run from WORK) imports isopatch
from that target, compares isopatch.__version__ with `isopatch --version` ("isopatch X.Y.Z") and meshes
the unit sphere (watertight, on the sphere) and lists the grids of a .vdb file with the plugin beside the
module. Last, the source tree has nothing new from pip, build or
setuptools (no *.egg-info, dist/, build/python-package, build/lib*, ...): they leave it as they found it.

Usage: python3 run_pip_test.py --source DIR --build-tree DIR --cli FILE --work DIR
"""

from __future__ import annotations

import argparse
import email.parser
import os
import shutil
import subprocess
import sys
import sysconfig
import time
import zipfile
from pathlib import Path

SPHERE_CHECK = """
import sys, numpy as np, isopatch
target = sys.argv[1]
assert isopatch.__file__.startswith(target + "/isopatch/"), (isopatch.__file__, target)
m = isopatch.mesh("x^2+y^2+z^2-1", box=((-1.2,) * 3, (1.2,) * 3), quality="preview")
radius = np.linalg.norm(m.vertices, axis=1)
topology = m.analyze(surface=False)["topology"]
assert len(m.vertices) > 100 and np.abs(radius - 1).max() < 1e-6, (len(m.vertices), np.abs(radius - 1).max())
assert topology["watertight"] and topology["euler_characteristic"] == 2, topology
# The .vdb reader: the plugin beside the module, not the build tree's.
import pyopenvdb, tempfile, os
grid = pyopenvdb.createLevelSetSphere(radius=1.0, voxelSize=0.1)
grid.name = "ball"
path = os.path.join(tempfile.mkdtemp(), "ball.vdb")
pyopenvdb.write(path, grids=[grid])
assert [g["name"] for g in isopatch.vdb_grids(path)] == ["ball"]
plugins = {line.split()[-1] for line in open("/proc/self/maps") if line.rstrip().endswith("isopatch_openvdb.so")}
assert plugins == {target + "/isopatch/isopatch_openvdb.so"}, plugins
print(isopatch.__version__)
"""


def fail(message: str) -> None:
    print(f"package.pip: FAILED: {message}", flush=True)
    sys.exit(1)


def run(command: list[str], **kwargs: object) -> str:
    start = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)  # type: ignore[call-overload]
    shown = " ".join("<code>" if "\n" in word else word for word in command)
    print(f"package.pip: {time.monotonic() - start:5.1f} s  {shown}", flush=True)
    if result.returncode != 0:
        fail(f"exit code {result.returncode}\n{result.stdout}\n{result.stderr}")
    return str(result.stdout)


def source_state(source: Path) -> set[str]:
    """What pip, build and setuptools could leave in the source tree (not `git status`: others may be
    editing the tree meanwhile)."""
    patterns = ("*.egg-info", "python/*.egg-info", "python/isopatch/*.egg-info", "dist", "isopatch",
                "build/python-package", "build/setuptools", "build/lib*", "build/bdist*", "build/temp*",
                "python/isopatch/_isopatch*.so")
    return {str(path.relative_to(source)) for pattern in patterns for path in source.glob(pattern)}


def check_wheel(wheel: Path, source: Path, version: str) -> None:
    tag = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    expected_name = f"isopatch-{version}-{tag}-{tag}-{platform}.whl"
    if wheel.name != expected_name:
        fail(f"the wheel is {wheel.name}, expected {expected_name} (a platform wheel of the tool's version)")
    with zipfile.ZipFile(wheel) as archive:
        names = archive.namelist()
        package = {name.removeprefix("isopatch/") for name in names if name.startswith("isopatch/")}
        metadata = email.parser.Parser().parsestr(archive.read(f"isopatch-{version}.dist-info/METADATA").decode())
        wheel_info = archive.read(f"isopatch-{version}.dist-info/WHEEL").decode()
    python_files = {path.name for path in (source / "python" / "isopatch").glob("*.py")}
    module = "_isopatch" + sysconfig.get_config_var("EXT_SUFFIX")
    expected = python_files | {"py.typed", "_isopatch.pyi", module, "isopatch_openvdb.so"}
    if package != expected:
        fail(f"the wheel's isopatch/ holds {sorted(package)}, expected {sorted(expected)} (missing: "
             f"{sorted(expected - package)}, extra: {sorted(package - expected)}; python/CMakeLists.txt "
             f"ISOPATCH_PYTHON_SOURCES lists the package's files)")
    outside = [name for name in names if not name.startswith(("isopatch/", f"isopatch-{version}.dist-info/"))]
    if outside:
        fail(f"the wheel holds files outside isopatch/: {outside}")
    if "Root-Is-Purelib: false" not in wheel_info:
        fail(f"the wheel is marked pure:\n{wheel_info}")
    if metadata["Name"] != "isopatch" or metadata["Version"] != version:
        fail(f"the wheel's metadata names {metadata['Name']} {metadata['Version']}")
    requires = metadata.get_all("Requires-Dist") or []
    if "numpy" not in requires or "distributed" not in metadata.get_all("Provides-Extra", []):
        fail(f"the wheel's dependencies: {requires}, extras {metadata.get_all('Provides-Extra')}")


def check_target(target: Path, work: Path, version: str) -> None:
    """A fresh interpreter imports isopatch from target alone, with the tool's version, and meshes a sphere."""
    env = {**os.environ, "PYTHONPATH": str(target), "PYTHONNOUSERSITE": "1"}
    imported = run([sys.executable, "-c", SPHERE_CHECK, str(target)], cwd=work, env=env).strip()
    if imported != version:
        fail(f"isopatch.__version__ from {target} is {imported!r}, `isopatch --version` says {version!r}")
    for name in ("py.typed", "_isopatch.pyi", "__init__.py"):
        if not (target / "isopatch" / name).exists():
            fail(f"{target}/isopatch has no {name}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("--build-tree", type=Path, required=True)
    parser.add_argument("--cli", type=Path, required=True)
    parser.add_argument("--work", type=Path, required=True)
    args = parser.parse_args()
    source, work = args.source.resolve(), args.work.resolve()
    for module, debian in (("pip", "python3-pip"), ("build", "python3-build"), ("setuptools", "python3-setuptools"),
                           ("wheel", "python3-wheel")):
        if subprocess.run([sys.executable, "-c", f"import {module}"], cwd="/", capture_output=True).returncode:
            fail(f"{sys.executable} has no module {module} (Debian: apt-get install {debian})")

    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    cli_version = run([str(args.cli), "--version"]).split()
    if len(cli_version) != 2 or cli_version[0] != "isopatch":
        fail(f"`isopatch --version` printed {cli_version}, expected 'isopatch X.Y.Z'")
    version = cli_version[1]

    before = source_state(source)
    env = {**os.environ, "ISOPATCH_CMAKE_BUILD_DIR": str(args.build_tree.resolve()), "PIP_NO_CACHE_DIR": "1",
           "PIP_DISABLE_PIP_VERSION_CHECK": "1", "PYTHONNOUSERSITE": "1"}
    env.pop("PYTHONPATH", None)
    run([sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", str(work / "dist"), str(source)],
        cwd=work, env=env)
    wheels = sorted((work / "dist").glob("*.whl"))
    if len(wheels) != 1:
        fail(f"python3 -m build made {wheels}")
    check_wheel(wheels[0], source, version)
    pip = [sys.executable, "-m", "pip", "install", "--no-deps", "--no-index", "--quiet"]
    run(pip + ["--no-build-isolation", "--target", str(work / "site"), str(source)], cwd=work, env=env)
    run(pip + ["--target", str(work / "site2"), str(wheels[0])], cwd=work, env=env)
    after = source_state(source)
    if after - before:
        fail(f"pip or build left in the source tree {source}: {sorted(after - before)}")

    check_target(work / "site", work, version)
    check_target(work / "site2", work, version)
    print(f"package.pip: {wheels[0].name} and `pip install .` import isopatch {version} and mesh the sphere")


if __name__ == "__main__":
    main()
