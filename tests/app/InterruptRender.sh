#!/bin/bash
# Ctrl-C (SIGINT) or a kill (SIGTERM) to a running `raylab render` (issue 14): it ends by
# that signal, the existing output is intact and no temporary file is left beside it.
#   InterruptRender.sh RAYLAB DIR
set -u -m  # -m: a background job of a script would otherwise ignore SIGINT
raylab=$1
dir=$2
for signal in INT TERM; do
  rm -rf "$dir"
  mkdir -p "$dir"
  printf 'old picture' > "$dir/out.ppm"
  "$raylab" render --size 640x480 --spp 1048576 --threads 1 --out "$dir/out.ppm" 2>/dev/null &
  pid=$!
  sleep 1
  kill -"$signal" "$pid"
  wait "$pid"
  code=$?
  expected=$((128 + $(kill -l "$signal")))
  [ "$code" -eq "$expected" ] || { echo "SIG$signal: exit code $code, expected $expected"; exit 1; }
  [ "$(cat "$dir/out.ppm")" = "old picture" ] || { echo "SIG$signal: out.ppm changed"; exit 1; }
  [ "$(ls -A "$dir")" = "out.ppm" ] || { echo "SIG$signal: left $(ls -A "$dir")"; exit 1; }
  echo "SIG$signal: render ended, old output intact, no temporary left"
done
