#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build with warnings as errors, run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs="$(nproc)"
cmake -S . -B build-test -G Ninja -DCMAKE_BUILD_TYPE=Release -DISOPATCH_WERROR=ON -DISOPATCH_BUILD_BENCH=ON >/dev/null
cmake --build build-test -j"$jobs"
ctest --test-dir build-test --output-on-failure -j"$jobs"
