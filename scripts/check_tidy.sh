#!/usr/bin/env bash
# The clang-tidy check: clang-tidy 14 (Debian's clang-tidy-14) with the checks of the repository's
# .clang-tidy over the sources of the library and the tool (src/**/*.cpp, apps/**/*.cpp; not tests,
# benchmarks or fuzz targets) and the repository headers they include, one process per core. Every
# enabled check is an error (WarningsAsErrors): fails listing the findings and their count per check.
# A full run takes about 7 minutes on 2 cores; a source that passed is not analysed again until it,
# a header it includes, its compile command, .clang-tidy or clang-tidy changes (scripts/check_tidy.py).
#
# Usage: scripts/check_tidy.sh [--no-cache] [-j N] [BUILD_DIR] [REGEX...]
#   BUILD_DIR   a configured build folder with compile_commands.json (default build-test; the top
#               CMakeLists.txt exports it); not a unity build such as build-sanitize
#   REGEX       only the sources whose path (src/..., apps/...) matches a REGEX, e.g. src/mesh/
#   --no-cache  analyse every source, whatever passed before
#   -j N        N clang-tidy processes (default: one per core)
# $CLANG_TIDY names another clang-tidy binary (default clang-tidy-14, else clang-tidy).
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
case "${1:-}" in -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
python=python3
[ -x /usr/bin/python3 ] && python=/usr/bin/python3  # Debian's, whatever else is first on PATH
exec "$python" -B "$repo/scripts/check_tidy.py" --repo "$repo" "$@"  # BUILD_DIR: from the caller's folder
