#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build with warnings as errors, run the whole test
# suite; then build again with the address and undefined-behaviour sanitizers and run it once more
# (every test but the packages, the Python package and the browser, see below); then the fuzzers.
# Every phase runs whatever the one before found, and the run ends with one count over all phases
# (`N passed, N failed, N skipped`, failures and skips listed with their reasons). The sanitizer build
# is a unity build (16 sources per translation unit): half the compile time; the first pass compiles
# every source on its own.
# Right after the first build, the format check (scripts/check_format.sh: every C++ file as
# clang-format-14 formats it with .clang-format, seconds) and clang-tidy (scripts/check_tidy.sh
# build-test: the checks of .clang-tidy over src/ and apps/, about 7 minutes on 2 cores when nothing
# was analysed before, seconds for what passed unchanged). Each fails the run at its end, listing its
# findings (the tests still run, so one run shows everything). ISOPATCH_LINT=0 skips both.
# Set ISOPATCH_SKIP_SANITIZERS=1 to skip the second pass when iterating locally.
# Every phase prints the seconds since the start, so that a CI log shows where its time goes.
set -euo pipefail
cd "$(dirname "$0")/.."
phase() { echo "isopatch: [$((SECONDS / 60)) min $((SECONDS % 60)) s] $*"; }
rm -f build-test/junit.xml build-sanitize/junit.xml build-fuzz/*.status  # results of an earlier run
phase "installing what is missing"
scripts/install-deps.sh
jobs="$(nproc)"
phase "building build-test"
cmake -S . -B build-test -G Ninja -DCMAKE_BUILD_TYPE=Release -DISOPATCH_WERROR=ON -DISOPATCH_BUILD_BENCH=ON -DISOPATCH_BUILD_CGAL_PEER=OFF \
      -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build-test -j"$jobs"
lint=ok
if [ "${ISOPATCH_LINT:-1}" != 0 ]; then
  phase "format and clang-tidy"
  scripts/check_format.sh || lint="$lint format"
  scripts/check_tidy.sh build-test || lint="$lint clang-tidy"
fi
phase "the test suite (build-test)"
ctest --test-dir build-test --output-on-failure -j"$jobs" --output-junit "$PWD/build-test/junit.xml" || true
if [ "${ISOPATCH_SKIP_SANITIZERS:-0}" != 1 ]; then
  echo "isopatch: the same suite under AddressSanitizer and UndefinedBehaviorSanitizer"
  # -O1 as the sanitizers recommend (and half the compile time of -O3).
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
        -DISOPATCH_WERROR=ON -DISOPATCH_BUILD_BENCH=OFF -DISOPATCH_BUILD_PYTHON=OFF -DISOPATCH_SANITIZE=address,undefined \
        -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 >/dev/null
  phase "building build-sanitize"
  cmake --build build-sanitize -j"$jobs"
  phase "the test suite under the sanitizers"
  # tests/support/lsan.supp: leaks inside third-party libraries (libzip under lib3mf's reader, which
  # the 3MF writer's test reads the package back with). Every test of the first pass runs here but
  # those that need what this build leaves out by design: the Python package (label "python": a module
  # built with ASan would need the sanitizer runtime preloaded into the interpreter), the Debian and pip
  # packages (label "package") and the browser (label "browser", whose server code test_view runs).
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS="suppressions=$PWD/tests/support/lsan.supp" \
    ctest --test-dir build-sanitize --output-on-failure -j"$jobs" -LE "package|python|browser" \
      --output-junit "$PWD/build-sanitize/junit.xml" || true
fi
# Fuzz targets (fuzz/, libFuzzer with clang++, ASan + UBSan): every committed corpus input (including
# the regressions the fuzzers found) and then a seeded search of 60 seconds per target (eight targets,
# two at a time on CI's two cores), so a run is reproducible (seed 1) yet explores beyond the corpus.
# Longer searches: scripts/fuzz.sh SECONDS.
# ISOPATCH_FUZZ=0 skips this.
if [ "${ISOPATCH_FUZZ:-1}" != 0 ]; then
  phase "the fuzzers"
  scripts/fuzz.sh "${ISOPATCH_FUZZ_SECONDS:-60}" 100000000 || true
fi
phase "done"
# One count over every phase that ran (scripts/test_summary.py): failures and skips listed with their
# reasons; a phase that did not reach its end counts as failed.
results=("release=build-test/junit.xml")
[ "${ISOPATCH_SKIP_SANITIZERS:-0}" != 1 ] && results+=("sanitizers=build-sanitize/junit.xml")
[ "${ISOPATCH_FUZZ:-1}" != 0 ] && results+=("fuzzers=fuzz:build-fuzz")
status=0
/usr/bin/python3 scripts/test_summary.py "${results[@]}" || status=1
if [ "$lint" != ok ]; then
  echo "isopatch: failed:${lint#ok} (the findings are listed after the first build)" >&2
  status=1
fi
exit "$status"
