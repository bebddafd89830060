#!/usr/bin/env bash
# Regenerates the table and figures of Sipos & Salvi 2021 (WAIT) with isopatch: Table 1 (vertices and
# time, marching cubes against projection, one cube cell, three densities), Figures 1, 2, 5, 6, 7 and the
# five-sided patch in a general convex cell; the composite-surface figures of its section 4 by
# scripts/paper_ipatch.sh.
# Usage: scripts/reproduce_paper.sh [--small] [OUTDIR]      (default OUTDIR: docs/paper)
# Needs the built tool (build/bin/isopatch, or $ISOPATCH). --small uses tiny sizes (for the test suite).
set -euo pipefail
cd "$(dirname "$0")/.."
small=0
if [ "${1:-}" = "--small" ]; then small=1; shift; fi
out="${1:-docs/paper}"
tool="${ISOPATCH:-build/bin/isopatch}"
[ -x "$tool" ] || { echo "reproduce_paper: $tool not found; build first (scripts/run.sh)" >&2; exit 2; }
mkdir -p "$out"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

size=400x400; r=(10 13 20); grid=(16 24 36); fig_r=12; fig_grid=20
if [ "$small" = 1 ]; then size=160x160; r=(3 4 5); grid=(4 6 8); fig_r=4; fig_grid=6; fi

# The cell is the unit cube; the root cell of the projection mesher is that cube (depth 0).
cell="0,0,0,1,1,1"
# Figure 5: a 3-sided patch, an eighth of a sphere around one corner of the cell.
three="x^2 + y^2 + z^2 - 0.36"
# Figures 1, 2, 6, 7 and Table 1: a curved 6-sided patch (a corner and its three neighbours inside).
six="x + y + z - 1.5 + 0.4*((x - 0.5)^2 + (y - 0.5)^2 + (z - 0.5)^2)"
one_cell=(--box "$cell" --min-depth 0 --max-depth 0 --refinement-levels 0)
view=(--view 35,30 --size "$size" --projection orthographic)

field() { awk -v k="$1" '$1 == k { gsub(",", "", $2); print $2 }' "$2"; }
millis() { awk '$1 == "time" { printf "%.1f", 1000 * $2 }' "$1"; }

# --- Table 1 ---------------------------------------------------------------------------------------
table="$out/table1.md"
{
  echo "| MC vertices | MC time (ms) | projection vertices | projection time (ms) | r | MC grid |"
  echo "|---:|---:|---:|---:|---:|---:|"
} > "$table"
for i in 0 1 2; do
  "$tool" mesh "$six" "${one_cell[@]}" --resolution "${r[$i]}" -o "$tmp/p$i.ply" > "$tmp/p$i.txt"
  "$tool" mesh "$six" --box "$cell" --method mc --grid "${grid[$i]}" -o "$tmp/m$i.ply" > "$tmp/m$i.txt"
  echo "| $(field vertices "$tmp/m$i.txt") | $(millis "$tmp/m$i.txt") | $(field vertices "$tmp/p$i.txt") | $(millis "$tmp/p$i.txt") | ${r[$i]} | ${grid[$i]} |" >> "$table"
done

# --- Figures ------------------------------------------------------------------------------------------
render() { "$tool" render "$1" -o "$2" "${view[@]}" -q "${@:3}"; }
"$tool" mesh "$six" --box "$cell" --method mc --grid "$fig_grid" -o "$tmp/mc6.ply" -q
"$tool" mesh "$six" --box "$cell" --method mc --grid "$fig_grid" --fair 10 -o "$tmp/mcfair6.ply" -q
"$tool" mesh "$six" "${one_cell[@]}" --resolution "$fig_r" -o "$tmp/proj6.ply" -q
"$tool" mesh "$three" --box "$cell" --method mc --grid "$fig_grid" -o "$tmp/mc3.ply" -q
"$tool" mesh "$three" "${one_cell[@]}" --resolution "$fig_r" -o "$tmp/proj3.ply" -q

# A shared colour range per figure, so that the two pictures compare.
range6=1; range3=3
render "$tmp/mc6.ply" "$out/fig1_mc_wireframe.png" --show wireframe
render "$tmp/mc6.ply" "$out/fig1_mc_mean_curvature.png" --show mean-curvature --surface "$six" --box "$cell" --range $range6
render "$tmp/mcfair6.ply" "$out/fig2_mc_fair_wireframe.png" --show wireframe
render "$tmp/mcfair6.ply" "$out/fig2_mc_fair_mean_curvature.png" --show mean-curvature --surface "$six" --box "$cell" --range $range6
render "$tmp/mc3.ply" "$out/fig5_mc_mean_curvature.png" --show mean-curvature --surface "$three" --box "$cell" --range $range3
render "$tmp/proj3.ply" "$out/fig5_projection_mean_curvature.png" --show mean-curvature --surface "$three" --box "$cell" --range $range3
render "$tmp/mc6.ply" "$out/fig6_mc_mean_curvature.png" --show mean-curvature --surface "$six" --box "$cell" --range $range6
render "$tmp/proj6.ply" "$out/fig6_projection_mean_curvature.png" --show mean-curvature --surface "$six" --box "$cell" --range $range6
render "$tmp/mc6.ply" "$out/fig6_mc_isophotes.png" --show isophotes
render "$tmp/proj6.ply" "$out/fig6_projection_isophotes.png" --show isophotes
"$tool" mesh "$six" --box "$cell" --method mc --grid "${grid[0]}" -o "$tmp/mc_t.ply" -q
"$tool" mesh "$six" "${one_cell[@]}" --resolution "${r[0]}" -o "$tmp/proj_t.ply" -q
render "$tmp/mc_t.ply" "$out/fig7_mc_wireframe.png" --show wireframe
render "$tmp/proj_t.ply" "$out/fig7_projection_wireframe.png" --show wireframe

# The five-sided patch (sec. 2: "any convex partitioning which is made of planar cuts"): one general
# convex cell, the box cut by five oblique planes around the z axis, holding a curved sheet that crosses
# its five slanted side faces; one cell (depth 0, no refinement), meshed by projection alone.
five="z - 0.2 + 0.35*(x^2 + y^2) - 0.15*x*y"
five_box="-1,-1,-1,1,1,1"
five_cell="0.955336,0.295520,0.30,-0.75;0.014159,0.999900,-0.20,-0.75;-0.946586,0.322452,0.30,-0.75;"
five_cell+="-0.599181,-0.800614,-0.20,-0.75;0.576272,-0.817258,0.30,-0.75"
"$tool" mesh "$five" --box "$five_box" --region "$five_cell" --min-depth 0 --max-depth 0 --refinement-levels 0 \
  --resolution "$fig_r" --remesh 0 -o "$tmp/five.ply" > "$tmp/five.txt"
grep -q '^patches_5 *1$' "$tmp/five.txt" || { echo "reproduce_paper: the five-sided cell gave no 5-sided patch" >&2; exit 1; }
view5=(--view 20,55 --size "$size" --projection orthographic)
"$tool" render "$tmp/five.ply" -o "$out/five_sided_wireframe.png" "${view5[@]}" -q --show wireframe
"$tool" render "$tmp/five.ply" -o "$out/five_sided_mean_curvature.png" "${view5[@]}" -q --show mean-curvature \
  --surface "$five" --box "$five_box" --range 1
"$tool" render "$tmp/five.ply" -o "$out/five_sided_isophotes.png" "${view5[@]}" -q --show isophotes
"$tool" analyze "$tmp/five.ply" --surface "$five" --box "$five_box" --json > "$out/analysis_five.json"

# Curvature error of the figure meshes, for the text.
for m in mc6 mcfair6 proj6; do
  "$tool" analyze "$tmp/$m.ply" --surface "$six" --box "$cell" --json > "$out/analysis_$m.json"
done
# Section 4: composite surfaces (I-patches of a control polyhedron, setback vertex blends).
if [ "$small" = 1 ]; then bash scripts/paper_ipatch.sh --small "$out"; else bash scripts/paper_ipatch.sh "$out"; fi
echo "reproduce_paper: wrote $table and the figures in $out"
