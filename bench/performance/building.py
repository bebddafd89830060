"""Configuring and building what the performance report runs (the peers, and isopatch itself when no
binary is given), with the commands a developer would type; the tools' paths, "" for a missing peer."""

import os
import shutil
import subprocess

PEERS = ["isopatch_cgal_peer", "isopatch_cgal_remesh", "isopatch_vtk_peer"]
OPTIONS = ["-DISOPATCH_BUILD_BENCH=ON", "-DISOPATCH_BUILD_CGAL_PEER=ON", "-DISOPATCH_BUILD_VTK_PEER=ON"]


def _run(args: list[str], cwd: str, log) -> None:
    log("$ " + " ".join(args))
    subprocess.run(args, cwd=cwd, check=True, stdout=subprocess.DEVNULL if args[0] == "cmake" and "-S" in args
                   else None)


def build(repo: str, build_dir: str, want_isopatch: bool, log) -> None:
    """Installs the benchmark's Debian packages (scripts/install-deps.sh --bench), configures
    `build_dir` (Release, benchmarks and peers on) and builds the peers CMake can build.
    \\raise subprocess.CalledProcessError when a step fails"""
    _run(["scripts/install-deps.sh", "--bench"], repo, log)
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        _run(["cmake", "-S", ".", "-B", build_dir, *generator, "-DCMAKE_BUILD_TYPE=Release"], repo, log)
    _run(["cmake", "-S", ".", "-B", build_dir, *OPTIONS], repo, log)
    listed = subprocess.run(["cmake", "--build", build_dir, "--target", "help"], cwd=repo, capture_output=True,
                            text=True, check=False).stdout
    targets = (["isopatch_cli"] if want_isopatch else []) + [t for t in PEERS if t in listed]
    if targets:
        _run(["cmake", "--build", build_dir, "--target", *targets, "-j", str(os.cpu_count() or 1)], repo, log)


def peer(build_dir: str, name: str, log) -> str:
    path = os.path.join(build_dir, "bin", name)
    if os.access(path, os.X_OK):
        return path
    log(f"{path} not built (its library not found?): its rows will say so")
    return ""
