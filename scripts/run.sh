#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and mesh the default example (the torus).
# The mesh is written to out/torus.ply (any PLY viewer opens it: MeshLab, Blender, ParaView).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DISOPATCH_BUILD_TESTS=OFF -DISOPATCH_BUILD_BENCH=OFF >/dev/null
cmake --build build --target isopatch_cli -j"$(nproc)"
mkdir -p out
build/bin/isopatch mesh torus -o out/torus.ply "$@"
echo "isopatch: the mesh is in $(pwd)/out/torus.ply (the tool is build/bin/isopatch; try 'build/bin/isopatch --help')"
