#!/usr/bin/env bash
# The performance report (the targets of issue 34): isopatch (default on 1, 2 and 4 threads, preview,
# fine, the default and fine at one level, the paper's method alone), CGAL's Surface_mesher, VTK Flying
# Edges and Flying Edges + CGAL's isotropic remeshing side by side in one run, at matched vertex counts
# (about 20k and 200k) on every public closed surface, plus one isopatch mesh of about 1M vertices with
# its peak memory and Flying Edges at its count; writes docs/performance.md, ratios first.
#
# Usage: scripts/performance_report.sh [--quick] [--no-build] [--surfaces a,b,...] [--repeats N]
#                                      [--sizes 20k,200k] [--large N] [--build DIR] [--out FILE]
#                                      [--from-results FILE] [ISOPATCH_BIN]
#   ISOPATCH_BIN  the isopatch binary to measure (default: DIR/bin/isopatch, built here)
#   --build DIR   build folder of the peers (default: $ISOPATCH_BUILD, else build-bench); configured
#                 and built here (isopatch_cgal_peer, isopatch_cgal_remesh, isopatch_vtk_peer, and
#                 isopatch_cli without ISOPATCH_BIN) unless --no-build
#   --quick       sphere, torus and tanglecube at about 20k vertices only (the large mesh still runs)
#   --surfaces    only these public closed surfaces
#   --sizes       only these sizes (20k, 200k)
#   --repeats N   timed runs per system, minimum kept (default 3)
#   --large N     vertices of the large mesh (default 1000000; 0: none)
#   --out FILE    the report (default docs/performance.md); results.json goes to out/performance/
#   --from-results FILE  rebuild the report from an earlier run's results.json, measuring nothing
# Needs Debian's libcgal-dev, libvtk9-dev and time (installed with scripts/install-deps.sh --bench
# unless --no-build) and python3 (standard library only). A missing peer gives rows saying so.
# Method: the last section of docs/performance.md (bench/performance/report.py).
set -euo pipefail
caller="$(pwd)"
cd "$(dirname "$0")/.."
case "${1:-}" in -h|--help) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
python=python3
[ -x /usr/bin/python3 ] && python=/usr/bin/python3  # Debian's, whatever else is first on PATH
exec "$python" -B bench/performance/driver.py --repo "$(pwd)" --cwd "$caller" --command "scripts/performance_report.sh $*" "$@"
