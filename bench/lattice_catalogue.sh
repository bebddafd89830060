#!/usr/bin/env bash
# The lattice catalogue of docs/lattices.md: each TPMS as a solid (f < 0) and a sheet (|f| - t < 0)
# capped by the box of two periods (CUT=box), cut by the ball of radius 6 (CUT=ball), inside the cylinder
# of radius 6 capped at z = +-6 (CUT=cylinder), or inside a ball of radius 8 that the box [-6, 6]^3 cuts
# open (CUT=open), capped by the box of two periods with a solid ball of radius 3 in it (CUT=insert: the
# union min(lattice, ball)) or a spherical void of radius 3 (CUT=void: max(lattice, -ball)), or filling a
# ball of radius 5.5 inside a spherical skin 0.5 thick (CUT=skin: max(r - 6, min(lattice, 5.5 - r))), meshed at 1/N
# of the part's side (diameter); prints one Markdown row per part
# (whole-process seconds timed from outside, vertices, watertight/manifold/outward, self-intersections,
# smallest angle, valence-6 share) or the exit code and message of a refusal.
# Usage: bench/lattice_catalogue.sh [ISOPATCH_BIN] [SHEET_T] [N] [CUT]
#        (default build-test/bin/isopatch, 0.3, 60, box)
set -uo pipefail
bin="${1:-build-test/bin/isopatch}"
t="${2:-0.3}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
declare -A tpms=(
  [gyroid]="sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)"
  [diamond]="sin(x)*sin(y)*sin(z)+sin(x)*cos(y)*cos(z)+cos(x)*sin(y)*cos(z)+cos(x)*cos(y)*sin(z)"
  [schwarz_p]="cos(x)+cos(y)+cos(z)"
  [neovius]="3*(cos(x)+cos(y)+cos(z))+4*cos(x)*cos(y)*cos(z)"
  [iwp]="2*(cos(x)*cos(y)+cos(y)*cos(z)+cos(z)*cos(x))-(cos(2*x)+cos(2*y)+cos(2*z))"
)
divisor="${3:-60}"
box="-6.6,-6.6,-6.6,6.6,6.6,6.6"
if [ "${4:-box}" = ball ]; then
  cap="x*x+y*y+z*z-36"
  edge=$(awk -v n="$divisor" 'BEGIN { printf "%.6f", 12 / n }')  # the diameter 12 over N
elif [ "${4:-box}" = cylinder ]; then
  cap="max(x*x+y*y-36,abs(z)-6)"
  edge=$(awk -v n="$divisor" 'BEGIN { printf "%.6f", 12 / n }')  # the diameter and height 12 over N
elif [ "${4:-box}" = skin ]; then
  cap="sqrt(x*x+y*y+z*z)-6"
  edge=$(awk -v n="$divisor" 'BEGIN { printf "%.6f", 12 / n }')  # the diameter 12 over N
elif [ "${4:-box}" = open ]; then
  cap="x*x+y*y+z*z-64"
  box="-6,-6,-6,6,6,6"
  edge=$(awk -v n="$divisor" 'BEGIN { printf "%.6f", 12 / n }')  # the box's side 12 over N
else
  cap="max(max(abs(x),abs(y)),abs(z))-2*pi"
  edge=$(awk -v n="$divisor" 'BEGIN { printf "%.6f", 4 * atan2(0, -1) / n }')  # the side 4 pi over N
fi
ball="x*x+y*y+z*z-9"
# The lattice $1 with the insert or the void of mode $2 (insert, void), or alone.
with_ball() {
  case "$2" in
    insert) echo "min($1,$ball)" ;;
    void) echo "max($1,-($ball))" ;;
    skin) echo "min($1,5.5-sqrt(x*x+y*y+z*z))" ;;
    *) echo "$1" ;;
  esac
}
echo "| part | kind | exit | seconds (whole) | vertices | closed, manifold, outward | self-intersections | smallest angle | valence 6 |"
echo "|---|---|---|---|---|---|---|---|---|"
for name in gyroid diamond schwarz_p neovius iwp; do
  f="${tpms[$name]}"
  for kind in solid sheet; do
    if [ "$kind" = solid ]; then lattice="$f"; else lattice="abs($f)-$t"; fi
    part="max($(with_ball "$lattice" "${4:-box}"),$cap)"
    start=$(date +%s%N)
    "$bin" mesh "$part" --box "$box" --edge-length "$edge" -q -o "$out/m.ply" 2>"$out/err"
    rc=$?
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    seconds="$((ms / 1000)).$(printf %03d $((ms % 1000)))"
    if [ "$rc" != 0 ]; then
      echo "| $name | $kind | $rc | $(printf %.1f "$seconds") | - | $(tail -n 1 "$out/err" | cut -c1-120) | | | |"
      continue
    fi
    report=$("$bin" analyze "$out/m.ply")
    vertices=$(echo "$report" | sed -n 's/.*: \([0-9,]*\) vertices.*/\1/p' | head -n 1)
    closed=$(echo "$report" | sed -n 's/.*watertight \([a-z]*\), manifold \([a-z]*\).*outward \([a-z]*\).*/\1, \2, \3/p')
    # A part the box cuts open: the creases' rows say so (rounded creases leave a smooth mesh).
    grep -q "smooth surface" "$out/err" && closed="$closed (creases rounded)"
    finer=$(sed -n 's/.*meshed along them at edge length \([0-9.e-]*\).*/\1/p' "$out/err" | head -n 1)
    [ -n "$finer" ] && closed="$closed (at edge $finer)"
    [ "${4:-box}" = open ] && closed="$closed; $(echo "$report" | sed -n 's/.*boundary edges \([0-9,]*[0-9]\).*/\1/p') boundary edges"
    self=$(echo "$report" | sed -n 's/.*self-intersections \(.*\)/\1/p')
    angle=$(echo "$report" | sed -n 's/^min angle *min \([0-9.]*\).*/\1/p')
    valence=$(echo "$report" | sed -n 's/.*: \([0-9.]*%\) of valence 6.*/\1/p')
    echo "| $name | $kind | 0 | $(printf %.1f "$seconds") | $vertices | $closed | $self | $angle | $valence |"
  done
done
