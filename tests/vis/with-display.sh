#!/bin/sh
# Runs a command with an X display: as is when DISPLAY is set (e.g. under
# `xvfb-run -a ctest`), else inside its own `xvfb-run -a`. Debian's VTK needs X even for
# offscreen rendering. Used as CROSSCOMPILING_EMULATOR of the render tests, and by hand.
if [ -n "$DISPLAY" ]; then
  exec "$@"
fi
if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "with-display.sh: no DISPLAY and no xvfb-run; install xvfb or configure with" \
       "-DRAYLAB_ENABLE_RENDERING_TESTS=OFF" >&2
  exit 1
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
