#!/bin/bash
# Two `raylab render` processes writing one output at the same time (issue 14): each
# round both succeed, and the file left is complete and byte for byte one of the two
# images (each rendered alone first), with no temporary file beside it.
#   ConcurrentRenders.sh RAYLAB DIR [ROUNDS]
set -u
raylab=$1
dir=$2
rounds=${3:-6}
rm -rf "$dir"
mkdir -p "$dir/expected" "$dir/out"
render() {  # seed, output
  "$raylab" render --algorithm path --size 48x36 --spp 4 --threads 1 --seed "$1" --out "$2" \
    > /dev/null 2>&1
}
for ext in png ppm pfm; do
  render 1 "$dir/expected/a.$ext" && render 2 "$dir/expected/b.$ext" ||
    { echo "FAIL: the single renders failed"; exit 1; }
  cmp -s "$dir/expected/a.$ext" "$dir/expected/b.$ext" &&
    { echo "FAIL: seeds 1 and 2 give the same .$ext"; exit 1; }
  seen_a=0
  seen_b=0
  for ((round = 0; round < rounds; ++round)); do
    rm -f "$dir/out/"*
    render 1 "$dir/out/image.$ext" &
    first=$!
    render 2 "$dir/out/image.$ext" &
    second=$!
    wait "$first"
    code1=$?
    wait "$second"
    code2=$?
    [ "$code1" = 0 ] && [ "$code2" = 0 ] ||
      { echo "FAIL: .$ext round $round: exit codes $code1 and $code2"; exit 1; }
    left=$(ls -A "$dir/out")
    [ "$left" = "image.$ext" ] || { echo "FAIL: .$ext round $round left: $left"; exit 1; }
    if cmp -s "$dir/out/image.$ext" "$dir/expected/a.$ext"; then
      seen_a=$((seen_a + 1))
    elif cmp -s "$dir/out/image.$ext" "$dir/expected/b.$ext"; then
      seen_b=$((seen_b + 1))
    else
      echo "FAIL: .$ext round $round: the file is neither image"
      exit 1
    fi
  done
  echo ".$ext: $rounds rounds, one complete image each time (seed 1: $seen_a, seed 2: $seen_b), no temporary left"
done
echo "two renders into one output: passed"
