#!/usr/bin/env bash
# The performance report (issue 20): isopatch (default on 1, 2 and 4 threads, preview, fine), CGAL's
# Surface_mesher, VTK Flying Edges and Flying Edges + CGAL's isotropic remeshing side by side in one
# run, at matched vertex counts (about 20k and 200k) on every public closed surface, plus one
# isopatch mesh of about 1M vertices with its peak memory; writes docs/performance.md, ratios first.
#
# Usage: scripts/performance_report.sh [--quick] [--no-build] [--surfaces a,b,...] [--repeats N]
#                                      [--large N] [--build DIR] [--out FILE] [ISOPATCH_BIN]
#   ISOPATCH_BIN  the isopatch binary to measure (default: DIR/bin/isopatch, built here)
#   --build DIR   build folder of the peers (default: $ISOPATCH_BUILD, else build-bench); configured
#                 and built here (isopatch_cli, isopatch_cgal_peer, isopatch_cgal_remesh,
#                 isopatch_vtk_peer) unless --no-build
#   --quick       sphere, torus and tanglecube at about 20k vertices only (the large mesh still runs)
#   --surfaces    only these public closed surfaces
#   --repeats N   timed runs per system, minimum kept (default 3)
#   --large N     vertices of the large mesh (default 1000000; 0: none)
#   --out FILE    the report (default docs/performance.md); results.json goes to out/performance/
# Needs Debian's libcgal-dev, libvtk9-dev and time (installed here with scripts/install-deps.sh --bench
# unless --no-build) and python3 (standard library only). A missing peer gives rows saying so.
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$(pwd)"

extra=(); build=1; out="docs/performance.md"; build_dir="${ISOPATCH_BUILD:-build-bench}"; tool=""
shown="scripts/performance_report.sh"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) extra+=(--quick); shown+=" --quick" ;;
    --no-build) build=0 ;;
    --surfaces) extra+=(--surfaces "${2:?--surfaces needs a list}"); shown+=" --surfaces $2"; shift ;;
    --repeats) extra+=(--repeats "${2:?--repeats needs a number}"); shown+=" --repeats $2"; shift ;;
    --large) extra+=(--large "${2:?--large needs a number}"); shown+=" --large $2"; shift ;;
    --build) build_dir="${2:?--build needs a folder}"; shift ;;
    --out) out="${2:?--out needs a file}"; shift ;;
    -h|--help) sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "performance_report: unknown option $1" >&2; exit 2 ;;
    *) tool="$1" ;;
  esac
  shift
done
python=python3
[ -x /usr/bin/python3 ] && python=/usr/bin/python3
command -v "$python" >/dev/null || { echo "performance_report: python3 is needed" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "performance_report: /usr/bin/time is needed (Debian's time)" >&2; exit 2; }

if [ "$build" = 1 ]; then
  scripts/install-deps.sh --bench
  if [ ! -f "$build_dir/CMakeCache.txt" ]; then
    generator=(); command -v ninja >/dev/null && generator=(-G Ninja)
    cmake -S . -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
  fi
  cmake -S . -B "$build_dir" -DISOPATCH_BUILD_BENCH=ON -DISOPATCH_BUILD_CGAL_PEER=ON -DISOPATCH_BUILD_VTK_PEER=ON >/dev/null
  targets=()
  [ -z "$tool" ] && targets+=(isopatch_cli)
  available="$(cmake --build "$build_dir" --target help 2>/dev/null)"
  for t in isopatch_cgal_peer isopatch_cgal_remesh isopatch_vtk_peer; do
    grep -q "$t" <<<"$available" && targets+=("$t")
  done
  [ ${#targets[@]} -gt 0 ] && cmake --build "$build_dir" --target "${targets[@]}" -j "$(nproc)"
fi

[ -n "$tool" ] || tool="$build_dir/bin/isopatch"
[ -x "$tool" ] || { echo "performance_report: $tool not found; build first or drop --no-build" >&2; exit 2; }
peer() {  # the peer's path, or "" with a warning when it was not built
  if [ -x "$build_dir/bin/$1" ]; then echo "$build_dir/bin/$1"; else
    echo "performance_report: $build_dir/bin/$1 not built ($2 not found?): its rows will say so" >&2; echo ""; fi
}
cgal="$(peer isopatch_cgal_peer CGAL)"
remesh="$(peer isopatch_cgal_remesh CGAL)"
vtk="$(peer isopatch_vtk_peer VTK)"

work="out/performance"
mkdir -p "$work" "$(dirname "$out")"
exec "$python" -B bench/performance/driver.py --tool "$tool" --cgal "$cgal" --vtk "$vtk" --remesh "$remesh" \
  --out "$out" --work "$work" --repo "$repo" --command "$shown" ${extra[@]+"${extra[@]}"}
