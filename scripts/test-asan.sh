#!/usr/bin/env bash
# The AddressSanitizer + UBSan stage of the test suite (issue 14), built with Clang in
# build/asan-fuzz:
# - the core library and the test programs of its loaders and file formats (scene, mesh,
#   lesson and ray-tree readers, limits, atomic saves, transforms, shapes, the tracer, the
#   BVH, the offsets of secondary rays, the sampling warps),
#   with the `asan` preset's settings; their tests carry the CTest label `asan`;
# - the raylab executable (its command line, without the window) and its CLI tests that
#   need no display (`app.*` but the labels render, python and lessons);
# - the libFuzzer targets of tests/fuzz (scene, lesson and ray-tree readers, the OBJ, OFF,
#   PLY and STL readers, the reference cache and --set) on the same instrumented library, each fuzzed for
#   RAYLAB_FUZZ_SECONDS (10 by default: its seeds and a few thousand mutations; depth is the
#   nightly run's, doc/dev/TESTING.md "Fuzzing") from its seeds (CTest label `fuzz`).
# A subset, so the whole of scripts/test.sh stays well under 30 minutes on 2 cores: the
# full `asan` preset (VTK views, the window, Python) takes about 10 minutes more to build.
# scripts/test.sh runs it after the main tests; run alone: scripts/test-asan.sh [ctest args]
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
build=build/asan-fuzz
# raylab_asan_tests: every test program whose tests carry the label `asan`.
targets=(raylab_asan_tests raylab raylab_check_render raylab_check_picture
         FuzzScene FuzzLesson FuzzRayTree FuzzCache FuzzSet Fuzzobj Fuzzoff Fuzzply Fuzzstl)

# The asan preset's cache variables, without what the subset does not build, and -O1 -g1
# instead of RelWithDebInfo's -O2 -g: the sanitizers find the same, the build is cheaper
# (doc/dev/TESTING.md, "Sanitizers", has the figures) and the reports still name the lines.
# RAYLAB_BUILD_FUZZERS adds libFuzzer's coverage to every library (Clang only).
CC=clang CXX=clang++ cmake --preset asan -B "$build" -DRAYLAB_BUILD_GUI=OFF \
  -DRAYLAB_BUILD_PYTHON=OFF -DRAYLAB_ENABLE_RENDERING_TESTS=OFF -DRAYLAB_BUILD_FUZZERS=ON \
  -DRAYLAB_FUZZ_SECONDS="${RAYLAB_FUZZ_SECONDS:-10}" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" > /dev/null
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}"
# Any report aborts the test (-fno-sanitize-recover); leaks count too.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
# --no-tests=error: a stage that finds no test fails (its label was once lost, and the
# stage passed without running anything).
status=0
ctest --test-dir "$build" -L 'asan|fuzz' --no-tests=error --output-on-failure \
  -j "$(nproc)" "$@" || status=$?
# The command line's tests that need no display (bad input, limits, options, renders to
# files), run on the sanitized raylab.
ctest --test-dir "$build" -R '^app\.' -LE 'render|python|lessons' --no-tests=error \
  --output-on-failure -j "$(nproc)" "$@" || status=$?
exit "$status"
