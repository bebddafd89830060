#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang++ (ASan + UBSan) and runs each for SECONDS (default
# 60) on its committed seed corpus (fuzz/corpus/<target>/), as many targets at a time as there are
# cores. Fails on any crash, leak, sanitizer report or timeout; the failing input is kept in
# fuzz/crashes/<target>/.
# Usage: scripts/fuzz.sh [SECONDS] [RUNS]
# With RUNS (CI passes one) the search is reproducible: a fixed seed and a fixed number of inputs, with
# SECONDS only as a cap; without it, each target simply runs for SECONDS with a random seed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
runs="${2:-}"
limits=(-max_total_time="$seconds")
[ -n "$runs" ] && limits+=(-seed=1 -runs="$runs")
targets=(fuzz_expression fuzz_mesh_reader fuzz_volume_reader fuzz_view_request fuzz_ipatch_reader fuzz_region fuzz_vdb_reader
  fuzz_self_intersection)

# clang with libFuzzer (Debian: clang + libclang-rt-14-dev), installed like scripts/install-deps.sh does.
missing=()
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "isopatch: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
cxx="$(command -v clang++ || command -v clang++-14)"

build=build-fuzz
CXX="$cxx" cmake -S fuzz -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" >/dev/null
cmake --build "$build" -j"$(nproc)"

# One target per core at a time (each still searches for SECONDS on its own core), reported in order.
fuzz_one() {
  local t="$1" work="$build/corpus/$1" crashes="fuzz/crashes/$1" max_len=4096
  [ "$t" = fuzz_vdb_reader ] && max_len=131072  # OpenVDB writes even a tiny grid's nodes in ~80 KB
  mkdir -p "$work" "$crashes"
  if ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 LSAN_OPTIONS=suppressions="$PWD/fuzz/lsan.supp" \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
       "$build/$t" "$work" "fuzz/corpus/$t" "${limits[@]}" -timeout=10 -rss_limit_mb=2048 \
       -max_len="$max_len" -artifact_prefix="$crashes/" -print_final_stats=1 >"$build/$t.log" 2>&1; then
    echo 0 >"$build/$t.status"
  else
    echo 1 >"$build/$t.status"
  fi
}
for t in "${targets[@]}"; do
  rm -f "$build/$t.status"
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
  echo "isopatch: fuzzing $t for ${seconds}s"
  fuzz_one "$t" &
done
wait || true

status=0
for t in "${targets[@]}"; do
  crashes="fuzz/crashes/$t"
  if [ "$(cat "$build/$t.status" 2>/dev/null || echo 1)" != 0 ]; then
    echo "isopatch: $t FAILED, input kept in $crashes/:"
    tail -n 40 "$build/$t.log"
    status=1
  else
    echo "isopatch: $t:"
    grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)" "$build/$t.log" || true
  fi
  rmdir "$crashes" 2>/dev/null || true   # keep the folder only when it holds a reproducer
done
rmdir fuzz/crashes 2>/dev/null || true
exit "$status"
