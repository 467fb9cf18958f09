#!/usr/bin/env bash
# Sets RayLab up, builds everything and runs the whole test suite. Tests that need
# OpenGL run inside a virtual X server (xvfb-run), so no display is needed.
#
#   scripts/test.sh [ctest arguments...]     e.g. scripts/test.sh -L core
#
# Without arguments it ends with the ASan + UBSan stage (scripts/test-asan.sh: the core
# library and its loader tests under AddressSanitizer and UBSan, and a short run of each
# fuzz target, built with Clang in build/asan-fuzz); skip it with RAYLAB_TEST_ASAN=0. The
# exit status is non-zero when either part failed.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" ci
cd "$here"
# The X server runs with -noreset: by default Xvfb resets whenever its last client leaves,
# and a test connecting during that reset was refused ("bad X server connection"; with two
# tests at a time, a few connections in a thousand). A test that fails is still run once
# more before it counts as failed; a real failure fails both times, and the log shows
# every retry.
status=0
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  ctest --preset ci --output-on-failure -j "$(nproc)" --repeat until-pass:2 "$@" || status=$?
# Then, on a full run, the AddressSanitizer + UBSan and fuzz stage (doc/dev/TESTING.md,
# "Sanitizers" and "Fuzzing").
if [[ $# -eq 0 && "${RAYLAB_TEST_ASAN:-1}" != 0 ]]; then
  echo "raylab test: the ASan + UBSan and fuzz stage (scripts/test-asan.sh; RAYLAB_TEST_ASAN=0 skips it)"
  "$here/scripts/test-asan.sh" || status=$?
fi
exit "$status"
