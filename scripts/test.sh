#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build with warnings as errors, run the whole test
# suite; then build again with the address and undefined-behaviour sanitizers and run it once more
# (without the installed-package test, the Python package (label "python": a module built with ASan
# would need the sanitizer runtime preloaded into the interpreter) and the two heaviest geometric
# sweeps, labels "adaptive" and
# "validation": every catalogue surface through the whole pipeline, 2.5 CPU minutes under the
# sanitizers; the unit and robustness labels still run the whole pipeline on many surfaces; and the
# browser tests of the viewer, label "browser", whose server code the unit test test_view runs; and
# five quality sweeps named below). The
# sanitizer build is a unity build (16 sources per translation unit): half the compile time; the first
# pass compiles every source on its own.
# Right after the first build, the format check (scripts/check_format.sh: every C++ file as
# clang-format-14 formats it with .clang-format, seconds) and clang-tidy (scripts/check_tidy.sh
# build-test: the checks of .clang-tidy over src/ and apps/, about 7 minutes on 2 cores when nothing
# was analysed before, seconds for what passed unchanged). Each fails the run at its end, listing its
# findings (the tests still run, so one run shows everything). ISOPATCH_LINT=0 skips both.
# Set ISOPATCH_SKIP_SANITIZERS=1 to skip the second pass when iterating locally.
# Every phase prints the seconds since the start, so that a CI log shows where its time goes.
set -euo pipefail
cd "$(dirname "$0")/.."
phase() { echo "isopatch: [${SECONDS} s] $*"; }
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
ctest --test-dir build-test --output-on-failure -j"$jobs"
if [ "${ISOPATCH_SKIP_SANITIZERS:-0}" != 1 ]; then
  echo "isopatch: the same suite under AddressSanitizer and UndefinedBehaviorSanitizer"
  # -O1 as the sanitizers recommend (and half the compile time of -O3).
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
        -DISOPATCH_WERROR=ON -DISOPATCH_BUILD_BENCH=OFF -DISOPATCH_BUILD_PYTHON=OFF -DISOPATCH_SANITIZE=address,undefined \
        -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 >/dev/null
  phase "building build-sanitize"
  cmake --build build-sanitize -j"$jobs"
  phase "the test suite under the sanitizers"
  # tests/support/lsan.supp: leaks inside third-party libraries (libzip under lib3mf's reader).
  # The list is one regular expression of ctest's (CMake's), which takes at most 10 parenthesised groups
  # and silently matches nothing beyond: one group here, the parameters' names end in " # GetParam() ...".
  # Also left out there: five quality sweeps (the error-bound levels, the fine preset over surfaces,
  # two convex-region sweeps, the composite CLI's region and frame) that took 380 of the pass's 1540
  # CPU seconds and run code the other sanitized tests run; they run in the first pass.
  heavy="^(Multiresolution.AnErrorBoundIsSingleLevelByDefaultAndAGivenLevelGradesTheBase"
  heavy="$heavy|QualityPresetsOverSurfaces.FineLowersTheCurvatureErrorOnTheGeometricMean"
  heavy="$heavy|ConvexMesh.UnboundedRegionWithoutABoxLiesInTheSurfacesBox"
  heavy="$heavy|ConvexMesh.CutsThatTurnFromABoxFaceOntoAPlaneStayOnBoth|CompositeCli.HonoursARegionAFrameAndTheBase"
  # And repeats of code the pass runs anyway (316 of its 2590 CPU seconds): three of the four output
  # formats of the CLI's thread-count check (the .ply one stays), the second library determinism check
  # of the same mesh, the genus-2 case of the error-bound sweep, the command line's thin-rim run (the
  # library's stays), and the comparisons of one block with one process (the blocks' own tests stay).
  cli_threads="Configurations/CliDeterminism.RunsWithOneTwoAndFourThreadsWriteTheSameBytes"
  heavy="$heavy|$cli_threads/genus2_coons_obj .*|$cli_threads/genus2_coons_off .*|$cli_threads/genus2_coons_stl .*"
  heavy="$heavy|Configurations/LibraryDeterminism.TwoCallsGiveTheSameMesh/genus2_coons .*"
  heavy="$heavy|Surfaces/MaxError.CentroidsStayWithinTheBoundOnAValidMesh/genus2 .*|LocalSizesCli.ThinRimRefinedWithAWarningUnlessUniform"
  heavy="$heavy|CreaseBlocks.OneBlockIsTheMeshOfOneProcessAlongTheCreases|Examples/CompositeBlocks.OneBlockIsTheMeshOfOneProcess/.*"
  # And seven more whose code the other sanitized tests run (163 CPU seconds): the paper's small
  # reproduction and the two checks of its outputs (I-patches, blends and Marching Cubes each have their
  # own tests), two thread-count determinism checks (genus 2 with the Coons base, a CSG shape;
  # one-thread and two-thread runs of the same code stay), and two composites of the automatic-level
  # sweep (its other examples stay).
  heavy="$heavy|paper\..*|CreaseMeshing.TheSameBytesForAnyNumberOfThreads"
  heavy="$heavy|Configurations/LibraryDeterminism.AnyThreadCountGivesTheSameMesh/genus2_coons .*"
  heavy="$heavy|Composite/RefinedExamples.AutomaticLevelIsNoWorseThanOneLevel/rounded_box .*"
  heavy="$heavy|Composite/RefinedExamples.AutomaticLevelIsNoWorseThanOneLevel/icosahedron_blend .*"
  # And the two gyroid runs of tiles by planes (the sphere's 125 tiles and the refusals run the same code),
  # and, for CI's 55 minutes (144 CPU seconds), the command line's narrow-cut run (the library's stays),
  # the default mesh in grazing boxes (their raw cut stays), the fine preset's level sweep, two formats of
  # the tangle cube's and one of the blobby's thread-count checks (the others stay), and the refusal of a
  # vertex in more than 65535 triangles (an allocation of that size, nothing else).
  heavy="$heavy|Tiles.EightTilesOfAGyroidAreWatertightOnTheSurfaceAndNearOneProcess|Tiles.TheSameBytesInAnyOrderAndForAnyThreadCount"
  heavy="$heavy|RegionCli.NarrowCutRefinedWithAWarningUnlessUniform|GrazingBoxes.DefaultMeshHoldsTheFloor"
  heavy="$heavy|Multiresolution.FineRefinesGentleSurfacesFurtherThanTheDefault|IncidenceLists.RefusesMoreThan65535EntriesAtOneVertex"
  heavy="$heavy|$cli_threads/tanglecube_preview_off .*|$cli_threads/tanglecube_preview_stl .*"
  heavy="$heavy|$cli_threads/blobby_max_error_stl .*"
  # And, for the OpenVDB input's build and tests (issue 39), seventeen more repeats (204 CPU seconds):
  # the error bound's halving (its centroid sweep stays), the curvature-guarded level two, a setback
  # solid's regions, a region plane on a lattice plane (the other convex meshes stay), the composite
  # CLI's two methods (its warnings stay), the curvature sweeps and blocked flips of the clean-up (every
  # default mesh runs both), creases off (the smooth path), one composite example (the others stay), the
  # mean edge length, two blobby and one tangle-cube determinism checks (their siblings stay), two
  # composites of the automatic-level sweep (the cube stays), and level one of the multiresolution.
  heavy="$heavy|MaxError.HalvingTheBoundRefinesTheMesh|Multiresolution.WhereTheCurvatureAsksForLevelOneTheGuardedLevelTwoBeatsIt"
  heavy="$heavy|SetbackSolid.RegionsOfNeighboursDoNotOverlapOnTheSurface|ConvexMesh.RegionPlaneOnOrNearALatticePlane"
  heavy="$heavy|CompositeCli.MeshesAFileByProjectionAndByMarchingCubes|Remesh.CurvatureSweepsLowerTheMeanCurvatureErrorAndKeepTheMeshValid"
  heavy="$heavy|ValenceFlips.BlockedFlipsGiveOneResultForAnyThreadCountAndStillLowerTheEnergy|CreaseMeshing.CreasesOffMeshesAsBefore"
  heavy="$heavy|Composite/Examples.MeshesClosedOnEveryPatchWithSmoothSeams/icosahedron_blend .*|ProjectionMesher.MeanEdgeIsTheRequestedEdgeLength"
  heavy="$heavy|Configurations/LibraryDeterminism.AnyThreadCountGivesTheSameMesh/blobby_max_error .*"
  heavy="$heavy|Configurations/LibraryDeterminism.TwoCallsGiveTheSameMesh/tanglecube_size_field .*"
  heavy="$heavy|$cli_threads/blobby_max_error_off .*|$cli_threads/blobby_max_error_obj .*"
  heavy="$heavy|Composite/RefinedExamples.AutomaticLevelIsNoWorseThanOneLevel/tapered_hexagonal_prism .*"
  heavy="$heavy|Composite/RefinedExamples.AutomaticLevelIsNoWorseThanOneLevel/pulled_box .*"
  heavy="$heavy|Multiresolution.LevelOneAndThePapersMethodAloneAreNotRefined"
  # And ten more (86 CPU seconds): three composites of the automatic-level sweep and three of the closed
  # examples (the cube, the octahedron blend, the pulled box and the tapered prism stay), the multiresolution's
  # thread-count check (the library's determinism checks stay), and the tangle cube's obj and the torus's
  # obj and stl thread-count runs (their ply runs stay).
  heavy="$heavy|Composite/RefinedExamples.AutomaticLevelIsNoWorseThanOneLevel/pentagonal_pyramid_blend .*"
  heavy="$heavy|Composite/RefinedExamples.AutomaticLevelIsNoWorseThanOneLevel/octahedron .*"
  heavy="$heavy|Composite/RefinedExamples.AutomaticLevelIsNoWorseThanOneLevel/dodecahedron .*"
  heavy="$heavy|Composite/Examples.MeshesClosedOnEveryPatchWithSmoothSeams/rounded_box .*"
  heavy="$heavy|Composite/Examples.MeshesClosedOnEveryPatchWithSmoothSeams/dodecahedron .*"
  heavy="$heavy|Composite/Examples.MeshesClosedOnEveryPatchWithSmoothSeams/pentagonal_pyramid_blend .*"
  heavy="$heavy|Multiresolution.SameBytesForOneTwoAndFourThreads|$cli_threads/tanglecube_preview_obj .*"
  heavy="$heavy|$cli_threads/torus_projection_obj .*|$cli_threads/torus_projection_stl .*"
  # And twelve more (91 CPU seconds) for the cold build of src/vdb, its test and its fuzz target: the
  # cusp analysis of the command line (the heart's warning stays), the composites' refinement thread
  # check, the default method, the error bound's split, the tapered prisms' folds (their example stays),
  # the rounded box in blocks (the cube stays), the preview floor on the tangle cube (the other surfaces
  # stay), a region plane with a frame in the multiresolution, the tangle cube's second library call,
  # and three octahedra of the composite sweeps (the cube and the pulled box stay).
  heavy="$heavy|SingularCli.AnalyzeGivesTheShapeAwayFromTheCusps|CompositeRefinement.SameBytesForAnyThreadCountAndAnExplicitLevel"
  heavy="$heavy|Cli.ProjectionIsTheDefaultMethod|MaxError.SplitsWhereTheCurvatureChangesWithinAnEdge"
  heavy="$heavy|PatchValidity.TheConstructionAvoidsTheFoldsOfTaperedPrisms"
  heavy="$heavy|Examples/CompositeBlocks.SixBlocksAreWatertightWithTheCurvesOwnPointsAndAsGoodAsOneProcess/rounded_box.ipatch"
  heavy="$heavy|Surfaces/QualityPresets.PreviewMeetsItsFloor/tanglecube .*|Multiresolution.ARegionPlaneAndAFrameKeepTheCutAndTheFloor"
  heavy="$heavy|Configurations/LibraryDeterminism.TwoCallsGiveTheSameMesh/tanglecube_preview .*"
  heavy="$heavy|Composite/RefinedExamples.AutomaticLevelIsNoWorseThanOneLevel/octahedron_blend .*"
  heavy="$heavy|Composite/Examples.MeshesClosedOnEveryPatchWithSmoothSeams/octahedron_blend .*"
  heavy="$heavy|Composite/Examples.MeshesClosedOnEveryPatchWithSmoothSeams/octahedron .*)$"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS="suppressions=$PWD/tests/support/lsan.supp" \
    ctest --test-dir build-sanitize --output-on-failure -j"$jobs" -LE "package|adaptive|validation|python|browser" \
      -E "$heavy"
fi
# Fuzz targets (fuzz/, libFuzzer with clang++, ASan + UBSan): every committed corpus input (including
# the regressions the fuzzers found) and then a seeded search of up to 20 seconds per target (seven
# targets on CI's two cores), so a run is reproducible (seed 1) yet explores beyond the corpus. Longer
# searches: scripts/fuzz.sh SECONDS.
# ISOPATCH_FUZZ=0 skips this.
if [ "${ISOPATCH_FUZZ:-1}" != 0 ]; then
  phase "the fuzzers"
  scripts/fuzz.sh "${ISOPATCH_FUZZ_SECONDS:-20}" 100000000
fi
phase "done"
if [ "$lint" != ok ]; then
  echo "isopatch: failed:${lint#ok} (the findings are listed after the first build)" >&2
  exit 1
fi
