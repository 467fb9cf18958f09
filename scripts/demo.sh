#!/usr/bin/env bash
# Sets RayLab up and runs it on the built-in default scene: opens the window where there
# is a display; renders the scene headless into PNG files where there is none.
#
#   scripts/demo.sh [output-dir]      (default output dir: out/)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" release raylab
raylab="$here/build/release/app/raylab"
out="${1:-$here/out}"

if [[ -n "${DISPLAY:-}" ]] && { ! command -v xdpyinfo >/dev/null || xdpyinfo >/dev/null 2>&1; }; then
  echo "raylab demo: opening the window on the default scene (display $DISPLAY)"
  exec "$raylab"
fi

mkdir -p "$out"
echo "raylab demo: no display; rendering the default scene headless (xvfb-run)"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$raylab" snapshot --size 1024x768 --out "$out/default-scene.png"
echo "raylab demo: wrote $out/default-scene.png"
