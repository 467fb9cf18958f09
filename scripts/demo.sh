#!/usr/bin/env bash
# Sets RayLab up and shows what it is for, on the built-in default scene: opens the window
# where there is a display; where there is none, makes the three pictures of its main job
# headless (in a virtual X server, xvfb-run) and prints where they are:
#   trace.png     one pixel's ray tree, bounce by bounce, drawn in 3D (and trace.json)
#   compare.png   the four algorithms side by side with their figures (and compare.json)
#   lesson-04-whitted/lesson.md    a lesson rendered step by step, with its pictures
#
#   scripts/demo.sh [output-dir]      (default output dir: out/)
#
# It builds in the same tree as scripts/test.sh (build/ci), so running one after the
# other builds RayLab once.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" ci raylab
raylab="$here/build/ci/app/raylab"
out="${1:-$here/out}"

if [[ -n "${DISPLAY:-}" ]] && { ! command -v xdpyinfo >/dev/null || xdpyinfo >/dev/null 2>&1; }; then
  echo "raylab demo: opening the window on the default scene (display $DISPLAY)"
  exec "$raylab"
fi

mkdir -p "$out"
echo "raylab demo: no display; drawing the default scene's main views headless (xvfb-run)"
headless() { xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$raylab" "$@"; }
# The pixel through the glass sphere, traced by Whitted's algorithm: reflection,
# refraction and shadow rays, as on the README's first picture.
headless trace --algorithm whitted --pixel 90 100 --out "$out/trace.png" --json "$out/trace.json"
headless compare --out "$out/compare.png" --json "$out/compare.json"
headless lesson "$here/lessons/04-whitted.json" --out "$out/lesson-04-whitted"
cat <<DONE
raylab demo: wrote
  $out/trace.png    the ray tree of pixel (90, 100), Whitted, in 3D ($out/trace.json: every ray)
  $out/compare.png  the four algorithms side by side with their figures ($out/compare.json)
  $out/lesson-04-whitted/lesson.md  lesson 4 (Whitted) step by step, with its pictures
DONE
