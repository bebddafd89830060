#!/usr/bin/env bash
# The pictures of where the projection mesh is imperfect before the clean-up, and of the preview's local
# repair, on the tanglecube (docs/algorithms.md 4.9): docs/raw-defects-tanglecube.png (the paper's method
# alone: slivers and irregular vertices cluster at patch corners and seams) and
# docs/preview-tanglecube.png (--quality preview, the same size). The numbers behind them are the
# statistics projection.defect_* of `isopatch mesh --stats-json`.
# Usage: scripts/defect_pictures.sh [ISOPATCH_BIN]   (default: build/bin/isopatch, built by scripts/run.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build/bin/isopatch}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$bin" mesh tanglecube --remesh 0 --edge-length 0.22 -o "$work/raw.ply" --stats-json "$work/raw.json" -q
grep -E '"defect_' "$work/raw.json" | tr -d ' ,'  # the numbers behind the picture
"$bin" render "$work/raw.ply" -o docs/raw-defects-tanglecube.png --show wireframe --size 900x900
"$bin" mesh tanglecube --quality preview --edge-length 0.22 -o "$work/preview.ply" -q
"$bin" render "$work/preview.ply" -o docs/preview-tanglecube.png --show wireframe --size 900x900
