#!/bin/bash
# `raylab lesson FILE --out DIR` over an earlier handout, stopped in the middle (issue 38):
# by Ctrl-C (SIGINT), a kill (SIGTERM) or kill -9 once its new folder holds a picture. The
# earlier handout stays whole; SIGINT and SIGTERM say so ("interrupted: DIR was not
# changed"); the next run leaves no new folder behind, even after kill -9.
#   InterruptHandout.sh RAYLAB SLOW_LESSON QUICK_LESSON DIR
set -u -m  # -m: a background job of a script would otherwise ignore SIGINT
raylab=$1
slow=$2
quick=$3
top=$4
out="$top/handout"
for signal in INT TERM KILL; do
  rm -rf "$top"
  mkdir -p "$out"
  printf 'old picture' > "$out/step-01.png"
  printf 'old handout' > "$out/lesson.md"
  "$raylab" lesson "$slow" --out "$out" > /dev/null 2> "$top.err" &
  pid=$!
  # Wait until the new folder beside DIR holds a picture (at most a minute).
  for _ in $(seq 600); do
    ls "$top"/.handout.raylab-new-*/step-*.png > /dev/null 2>&1 && break
    sleep 0.1
  done
  ls "$top"/.handout.raylab-new-*/step-*.png > /dev/null 2>&1 ||
    { echo "SIG$signal: no picture in a new folder"; cat "$top.err"; kill -9 "$pid"; exit 1; }
  kill -"$signal" "$pid"
  wait "$pid"
  code=$?
  expected=$((128 + $(kill -l "$signal")))
  [ "$code" -eq "$expected" ] || { echo "SIG$signal: exit code $code, expected $expected"; exit 1; }
  [ "$(cat "$out/step-01.png")" = "old picture" ] || { echo "SIG$signal: step-01.png changed"; exit 1; }
  [ "$(cat "$out/lesson.md")" = "old handout" ] || { echo "SIG$signal: lesson.md changed"; exit 1; }
  if [ "$signal" != KILL ]; then
    grep -q "raylab: interrupted: $out was not changed" "$top.err" ||
      { echo "SIG$signal: no message"; cat "$top.err"; exit 1; }
    [ "$(ls -A "$top")" = "handout" ] || { echo "SIG$signal: left $(ls -A "$top")"; exit 1; }
  fi
  # The next run replaces the handout whole and leaves nothing beside it.
  "$raylab" lesson "$quick" --out "$out" --size 32x24 > /dev/null ||
    { echo "SIG$signal: the next run failed"; exit 1; }
  [ "$(ls -A "$top")" = "handout" ] || { echo "SIG$signal: after the next run: $(ls -A "$top")"; exit 1; }
  [ "$(ls "$out")" = "$(printf 'lesson.md\nstep-01.png')" ] ||
    { echo "SIG$signal: the next run wrote $(ls "$out")"; exit 1; }
  echo "SIG$signal: the old handout intact, nothing left behind after the next run"
done
