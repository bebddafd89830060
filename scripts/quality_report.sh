#!/usr/bin/env bash
# The quality report (issue 7): meshes every public surface of docs/algorithms.md 7.4 at three
# sizes (about 2k, 10k and 40k vertices) with projection, marching cubes and, when CGAL is installed,
# CGAL's Surface_mesher at matched vertex counts; analyses every mesh with `isopatch analyze`; writes
# docs/quality.md with the metrics side by side, the time ratios of this run and the targets checked.
# A failed mesh or a missing CGAL gives a row saying so; the report is still written.
#
# Usage: scripts/quality_report.sh [--quick] [--no-build] [--surfaces a,b,...] [--out FILE] [BUILD_DIR]
#   BUILD_DIR   build folder (default: $ISOPATCH_BUILD, else build); configured and built here
#               (targets isopatch_cli, isopatch_ideal_lattice and, when CGAL is found, isopatch_cgal_peer)
#               unless --no-build
#   --quick     one size (about 2k vertices) for smoke testing
#   --surfaces  only these public surfaces
#   --out FILE  the report (default docs/quality.md); meshes and results.json go to out/quality/
# Needs python3 (standard library only). Method: docs/quality-method.md.
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$(pwd)"

quick=(); build=1; surfaces=""; out="docs/quality.md"; build_dir="${ISOPATCH_BUILD:-build}"
shown="scripts/quality_report.sh"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=(--quick); shown+=" --quick" ;;
    --no-build) build=0 ;;
    --surfaces) surfaces="${2:?--surfaces needs a list}"; shown+=" --surfaces $2"; shift ;;
    --out) out="${2:?--out needs a file}"; shift ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "quality_report: unknown option $1" >&2; exit 2 ;;
    *) build_dir="$1" ;;
  esac
  shift
done
command -v python3 >/dev/null || { echo "quality_report: python3 is needed" >&2; exit 2; }

if [ "$build" = 1 ]; then
  if [ ! -f "$build_dir/CMakeCache.txt" ]; then
    generator=(); command -v ninja >/dev/null && generator=(-G Ninja)
    cmake -S . -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
  fi
  # The peer target exists only when CMake found CGAL (bench/CMakeLists.txt); benchmarks must be on.
  cmake -S . -B "$build_dir" -DISOPATCH_BUILD_BENCH=ON -DISOPATCH_BUILD_CGAL_PEER=ON >/dev/null
  targets=(isopatch_cli isopatch_ideal_lattice)
  if cmake --build "$build_dir" --target help 2>/dev/null | grep -q isopatch_cgal_peer; then
    targets+=(isopatch_cgal_peer)
  fi
  cmake --build "$build_dir" --target "${targets[@]}" -j "$(nproc)"
fi

tool="$build_dir/bin/isopatch"
peer="$build_dir/bin/isopatch_cgal_peer"
[ -x "$tool" ] || { echo "quality_report: $tool not found; build first or drop --no-build" >&2; exit 2; }
if [ ! -x "$peer" ]; then
  echo "quality_report: $peer not built (CGAL not found?): the report will have no CGAL rows" >&2
  peer=""
fi

ideal="$build_dir/bin/isopatch_ideal_lattice"
if [ ! -x "$ideal" ]; then
  echo "quality_report: $ideal not built: the report will have no ideal-lattice yardstick" >&2
  ideal=""
fi

work="out/quality"
mkdir -p "$work" "$(dirname "$out")"
exec python3 -B bench/quality_report/main.py --tool "$tool" --peer "$peer" --ideal "$ideal" --out "$out" --work "$work" \
  --repo "$repo" --surfaces "$surfaces" --command "$shown" "${quick[@]}"
