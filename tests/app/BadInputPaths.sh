#!/bin/bash
# Bad-input rows that need a shell (issue 14): a scene file nobody may read, and file
# names that are not UTF-8 (bytes in argv). Each prints the message it checked, or
# "SKIP: reason" with exit code 77 (CTest SKIP_RETURN_CODE).
#   BadInputPaths.sh unreadable|non-utf8-argv RAYLAB DIR
set -u
mode=$1
raylab=$2
dir=$3
rm -rf "$dir"
mkdir -p "$dir"
scene='{"raylab_scene": 2, "materials": [{"name": "m"}],
 "objects": [{"name": "ball", "material": "m",
              "shape": {"type": "sphere", "centre": [0, 0, 0], "radius": 1}}],
 "point_lights": [{"name": "lamp", "position": [0, 5, 5], "intensity": [10, 10, 10]}]}'
fail() { echo "FAIL: $*"; exit 1; }

case $mode in
unreadable)
  printf '%s\n' "$scene" > "$dir/locked.json"
  chmod 000 "$dir/locked.json"
  run=("$raylab")
  if [ -r "$dir/locked.json" ]; then
    # Root reads a mode-000 file all the same: run raylab as the user nobody instead.
    if [ "$(id -u)" = 0 ] && command -v setpriv > /dev/null &&
       setpriv --reuid=65534 --regid=65534 --clear-groups "$raylab" --version > /dev/null 2>&1; then
      run=(setpriv --reuid=65534 --regid=65534 --clear-groups "$raylab")
    else
      echo "SKIP: running as $(id -un), who may read a file of mode 000, and cannot drop to nobody"
      exit 77
    fi
  fi
  "${run[@]}" render --scene "$dir/locked.json" --size 16x16 --out "$dir/out.png" 2> "$dir/err.txt"
  code=$?
  err=$(cat "$dir/err.txt")
  [ "$code" = 1 ] || fail "exit code $code, expected 1: $err"
  expected="raylab: error: $dir/locked.json: cannot open scene file: Permission denied"
  [ "$err" = "$expected" ] || fail "message '$err', expected '$expected'"
  [ ! -e "$dir/out.png" ] || fail "out.png was written"
  echo "unreadable: $err"
  ;;
non-utf8-argv)
  # Latin-1 "scène.json": the byte 0xe8 alone is not UTF-8.
  name=$(printf 'sc\xe8ne.json')
  printf '%s\n' "$scene" > "$dir/$name"
  "$raylab" render --scene "$dir/$name" --size 16x16 --spp 1 --out "$dir/out.png" > /dev/null 2>&1 ||
    fail "a valid scene with a Latin-1 name does not render"
  [ -s "$dir/out.png" ] || fail "no out.png from a valid scene with a Latin-1 name"
  # The same name with an error: the message quotes the byte as \xe8 (valid UTF-8 text).
  printf '{"raylab_scene": 2, "materials": [], "objects": [], "camera": {"width": -1}}' > "$dir/$name"
  "$raylab" render --scene "$dir/$name" --size 16x16 --out "$dir/out2.png" 2> "$dir/err.txt"
  code=$?
  err=$(cat "$dir/err.txt")
  [ "$code" = 1 ] || fail "exit code $code, expected 1: $err"
  expected="raylab: error: $dir/sc\\xe8ne.json: at /camera: width and height must be in [1, 8192], got -1 x 240"
  [ "$err" = "$expected" ] || fail "message '$err', expected '$expected'"
  iconv -f UTF-8 -t UTF-8 "$dir/err.txt" > /dev/null 2>&1 || fail "the message is not valid UTF-8"
  [ ! -e "$dir/out2.png" ] || fail "out2.png was written"
  echo "non-utf8-argv: valid scene rendered; $err"
  ;;
*)
  fail "unknown mode $mode"
  ;;
esac
