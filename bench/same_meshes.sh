#!/usr/bin/env bash
# Whether two builds of isopatch make the same meshes: meshes every catalogue surface with both tools in
# six configurations (default, --remesh 0, --base coons --remesh 0, --max-error 1e-3, --quality preview,
# --method mc) and every composite of examples/*.ipatch in three (default, --remesh 0, --method mc), and
# compares the files byte for byte; then prints vertices, valence-6 share and H nRMS of the catalogue's default
# meshes side by side. For refactors that must not change output.
#   bench/same_meshes.sh OLD_ISOPATCH NEW_ISOPATCH [OUTDIR]
set -euo pipefail
old=$1 new=$2 out=${3:-$(mktemp -d)}
surfaces=$("$new" surfaces | awk '/^[a-z_0-9]+ +(genus|open)/ {print $1}')
composites=$(ls "$(dirname "$0")"/../examples/*.ipatch)
configs=("default:" "raw:--remesh 0" "coons:--remesh 0 --base coons" "maxerr:--max-error 1e-3" "preview:--quality preview" "mc:--method mc")
composite_configs=("default:" "raw:--remesh 0" "mc:--method mc")
differ=0
compared=0
for s in $surfaces $composites; do
  if [[ $s == *.ipatch ]]; then set_configs=("${composite_configs[@]}"); else set_configs=("${configs[@]}"); fi
  for c in "${set_configs[@]}"; do
    compared=$((compared + 1))
    name=${c%%:*} args=${c#*:}
    for side in old new; do
      mkdir -p "$out/$side"
      tool=$old; [ "$side" = new ] && tool=$new
      # shellcheck disable=SC2086
      "$tool" mesh "$s" -o "$out/$side/$(basename "$s").$name.ply" --quiet $args || echo "exit $? for $side $s $name"
    done
    if ! cmp -s "$out/old/$(basename "$s").$name.ply" "$out/new/$(basename "$s").$name.ply"; then
      echo "DIFFERENT: $s $name"
      differ=$((differ + 1))
    fi
  done
done
echo "| surface | vertices old / new | valence 6 old / new | H nRMS old / new |"
echo "|---|---|---|---|"
for s in $surfaces; do
  row="| $s"
  for key in vertices share_6 nrms; do
    vals=""
    for side in old new; do
      v=$("$new" analyze "$out/$side/$s.default.ply" --surface "$s" --json | /usr/bin/python3 -c "
import json, sys
j = json.load(sys.stdin)
print({'vertices': j['mesh']['vertices'], 'share_6': round(100 * j['valence']['share_6'], 1),
       'nrms': '%.4g' % j['accuracy']['mean_curvature']['nrms']}['$key'])")
      vals="${vals:+$vals / }$v"
    done
    row="$row | $vals"
  done
  echo "$row |"
done
echo "$differ of $compared meshes differ (files in $out)"
[ "$differ" -eq 0 ]
