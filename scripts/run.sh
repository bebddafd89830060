#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, install the Python package for Debian's
# /usr/bin/python3 (into its site-packages, /usr/local/lib/python3.11/dist-packages: `import isopatch`
# then works from any folder), and mesh the default example (the torus).
# The mesh is written to out/torus.ply (any PLY viewer opens it: MeshLab, Blender, ParaView).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DISOPATCH_BUILD_TESTS=OFF -DISOPATCH_BUILD_BENCH=OFF \
      -DISOPATCH_BUILD_PYTHON=ON -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build --target isopatch_cli isopatch_python -j"$(nproc)"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO cmake --install build --component python >/dev/null
mkdir -p out
build/bin/isopatch mesh torus -o out/torus.ply "$@"
echo "isopatch: the mesh is in $(pwd)/out/torus.ply (the tool is build/bin/isopatch; try 'build/bin/isopatch --help')"
echo "isopatch: the Python package is installed for /usr/bin/python3 (try: /usr/bin/python3 -c 'import isopatch; help(isopatch.mesh)')"
