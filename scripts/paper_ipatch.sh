#!/usr/bin/env bash
# The paper's two figures of composite surfaces (Sipos & Salvi 2021, sec. 4), with isopatch: a composite
# of I-patches from a control polyhedron (examples/pulled_box.ipatch) by Marching Cubes and by projection
# (wireframe, mean curvature, isophotes), and setback vertex blends (examples/rounded_box.ipatch: a box
# with rounded edges and 8 six-sided vertex blends, 26 patches) by projection; and a table of the same
# metrics for both methods on both composites. Called by scripts/reproduce_paper.sh.
# Usage: scripts/paper_ipatch.sh [--small] OUTDIR
# Needs the built tool (build/bin/isopatch, or $ISOPATCH). --small uses tiny sizes (for the test suite).
set -euo pipefail
cd "$(dirname "$0")/.."
small=0
if [ "${1:-}" = "--small" ]; then small=1; shift; fi
out="${1:-docs/paper}"
tool="${ISOPATCH:-build/bin/isopatch}"
[ -x "$tool" ] || { echo "paper_ipatch: $tool not found; build first (scripts/run.sh)" >&2; exit 2; }
mkdir -p "$out"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

size=400x400; edge=0.06; grid=102; box_edge=0.04; box_grid=70
if [ "$small" = 1 ]; then size=160x160; edge=0.3; grid=16; box_edge=0.25; box_grid=20; fi
composite=examples/pulled_box.ipatch
setback=examples/rounded_box.ipatch
view=(--view 35,30 --size "$size")
render() { "$tool" render "$1" -o "$2" "${view[@]}" -q "${@:3}"; }

"$tool" mesh "$composite" --method mc --grid "$grid" -o "$tmp/composite_mc.ply" -q
# One level (--refine 1): the paper's pipeline with the clean-up per patch; the default refines it
# (docs/algorithms.md 8.7).
"$tool" mesh "$composite" --edge-length "$edge" --refine 1 -o "$tmp/composite_projection.ply" -q
"$tool" mesh "$setback" --method mc --grid "$box_grid" -o "$tmp/setback_mc.ply" -q
"$tool" mesh "$setback" --edge-length "$box_edge" --refine 1 -o "$tmp/setback_projection.ply" 2> "$tmp/setback.err" -q
for m in mc projection; do
  render "$tmp/composite_$m.ply" "$out/ipatch_${m}_wireframe.png" --show wireframe
  render "$tmp/composite_$m.ply" "$out/ipatch_${m}_mean_curvature.png" --show mean-curvature --surface "$composite" --range 1
  render "$tmp/composite_$m.ply" "$out/ipatch_${m}_isophotes.png" --show isophotes
done
render "$tmp/setback_projection.ply" "$out/setback_projection_wireframe.png" --show wireframe
render "$tmp/setback_projection.ply" "$out/setback_projection_mean_curvature.png" --show mean-curvature --surface "$setback" --range 4
render "$tmp/setback_projection.ply" "$out/setback_projection_isophotes.png" --show isophotes

# The same metrics for both methods: isopatch analyze against the composite surface.
table="$out/ipatch_table.md"
{
  echo "| composite | method | vertices | watertight | genus | valence 6 (%) | min angle (deg) | H nRMS | vertex normal error (deg, mean) | max vertex distance / diagonal |"
  echo "|---|---|---:|---|---:|---:|---:|---:|---:|---:|"
} > "$table"
for c in composite setback; do
  file=$composite; [ "$c" = setback ] && file=$setback
  for m in mc projection; do
    "$tool" analyze "$tmp/${c}_$m.ply" --surface "$file" --json > "$tmp/analysis_${c}_$m.json"
    python3 - "$tmp/analysis_${c}_$m.json" "$(basename "$file")" "$m" >> "$table" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
t, a = d["topology"], d["accuracy"]
method = {"mc": "Marching Cubes", "projection": "projection"}[sys.argv[3]]
print(f"| {sys.argv[2]} | {method} | {t['vertices']} | {'yes' if t['watertight'] else 'no'} | {t['genus']} | "
      f"{100 * d['valence']['share_6']:.1f} | {d['shape']['min_angle_degrees']['min']:.2f} | "
      f"{a['mean_curvature']['nrms']:.3f} | {a['vertex_normal_error_degrees']['mean']:.3f} | "
      f"{a['vertex_distance_relative']['max']:.1e} |")
PY
  done
done
echo "paper_ipatch: wrote $table and the composite figures in $out"
