#!/bin/bash
# `raylab animate --video` end to end with the real ffmpeg (issue 38, item 13):
#  1. into a folder and a video of an earlier run (6 frames), a run of 3 frames gives a
#     video of exactly 3 frames (counted by ffprobe): ffmpeg's glob sees this run's only;
#  2. an ffmpeg killed while writing, and Ctrl-C during the encoding, leave the earlier
#     video as it was (byte for byte), say so, and leave no half video beside it;
#  3. kill -9 during the encoding leaves the earlier video, and the next run removes the
#     half video beside it;
#  4. without ffmpeg on PATH: a clear error before any work, video and frames untouched.
# Skipped (exit 77, with the reason) only when ffmpeg or ffprobe is not installed.
#   AnimateVideo.sh RAYLAB DIR
set -u -m  # -m: a background job of a script would otherwise ignore SIGINT
raylab=$1
top=$2
if ! command -v ffmpeg > /dev/null || ! command -v ffprobe > /dev/null; then
  echo "SKIPPED: ffmpeg/ffprobe are not on PATH; install Debian's ffmpeg (scripts/setup.sh)"
  exit 77
fi
fail() { echo "FAILED: $*"; [ -f "$top/err" ] && cat "$top/err"; exit 1; }
rm -rf "$top"
mkdir -p "$top/bin"
frames="$top/frames"
video="$top/bounce.mp4"
animate=("$raylab" animate --pixel 5 5 --size 32x24 --no-captions --out "$frames")
count() {
  ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames \
    -of csv=p=0 "$1"
}
beside() { ls -A "$top" | grep -v '^\(bin\|frames\|bounce\.mp4\|err\|old\.mp4\|ready\)$'; }

# 1. An earlier run's 6 frames, then this run's 3 into the same folder and video.
"${animate[@]}" --frames 0:5 --video "$video" > /dev/null 2> "$top/err" || fail "first run"
[ "$(count "$video")" = 6 ] || fail "the first video has $(count "$video") frames, not 6"
"${animate[@]}" --frames 0:2 --video "$video" > /dev/null 2> "$top/err" || fail "second run"
[ "$(count "$video")" = 3 ] || fail "the second video has $(count "$video") frames, not 3"
[ "$(ls "$frames" | wc -l)" = 3 ] || fail "the folder holds $(ls "$frames")"
[ -z "$(beside)" ] || fail "left beside the video: $(beside)"
echo "stale frames: the video has this run's 3 frames"
cp "$video" "$top/old.mp4"

# 2a. An ffmpeg killed after writing half a video: the old video stays, with a message.
cat > "$top/bin/ffmpeg" << 'EOF'
#!/bin/sh
for last; do :; done
printf 'half a video' > "$last"
kill -9 $$
EOF
chmod +x "$top/bin/ffmpeg"
PATH="$top/bin:$PATH" "${animate[@]}" --frames 0:1 --video "$video" > /dev/null 2> "$top/err"
code=$?
[ "$code" = 1 ] || fail "killed ffmpeg: exit code $code, expected 1"
grep -q "bounce\.mp4: ffmpeg failed (stopped by signal 9); the video was not changed" "$top/err" ||
  fail "killed ffmpeg: no message"
cmp -s "$video" "$top/old.mp4" || fail "killed ffmpeg: the video changed"
[ -z "$(beside)" ] || fail "killed ffmpeg: left $(beside)"
echo "killed ffmpeg: the old video intact, nothing left beside it"

# 2b/3. Ctrl-C (SIGINT to the whole process group, as a terminal sends it) and kill -9 while
# ffmpeg writes.
cat > "$top/bin/ffmpeg" << EOF
#!/bin/sh
for last; do :; done
printf 'half a video' > "\$last"
touch "$top/ready"
sleep 60
EOF
for signal in INT KILL; do
  rm -f "$top/ready"
  PATH="$top/bin:$PATH" "${animate[@]}" --frames 0:1 --video "$video" > /dev/null 2> "$top/err" &
  pid=$!
  for _ in $(seq 600); do
    [ -f "$top/ready" ] && break
    sleep 0.1
  done
  [ -f "$top/ready" ] || { kill -9 -- -"$pid"; fail "SIG$signal: ffmpeg did not start"; }
  kill -"$signal" -- -"$pid"
  wait "$pid"
  code=$?
  cmp -s "$video" "$top/old.mp4" || fail "SIG$signal: the video changed"
  if [ "$signal" = INT ]; then
    [ "$code" = 1 ] || fail "SIGINT: exit code $code, expected 1"
    grep -q "ffmpeg failed (stopped by signal 2); the video was not changed" "$top/err" ||
      fail "SIGINT: no message"
    [ -z "$(beside)" ] || fail "SIGINT: left $(beside)"
  else
    [ "$code" = 137 ] || fail "SIGKILL: exit code $code, expected 137"
    [ -n "$(beside)" ] || fail "SIGKILL: no half video beside the old one (the test is wrong)"
    "${animate[@]}" --frames 0:3 --video "$video" > /dev/null 2> "$top/err" || fail "next run"
    [ "$(count "$video")" = 4 ] || fail "after SIGKILL, the next video has $(count "$video") frames"
    [ -z "$(beside)" ] || fail "SIGKILL: the next run left $(beside)"
    cp "$video" "$top/old.mp4"
  fi
  echo "SIG$signal during the encoding: the old video intact, nothing left behind"
done

# 4. No ffmpeg on PATH: the error comes first; the video and the frames are as they were.
ls "$frames" > "$top/ready"
PATH="$top/empty" "${animate[@]}" --frames 0:1 --video "$video" > /dev/null 2> "$top/err"
code=$?
[ "$code" = 1 ] || fail "no ffmpeg: exit code $code, expected 1"
grep -q "needs the ffmpeg encoder, which is not on PATH; install it with .sudo apt-get install ffmpeg." \
  "$top/err" || fail "no ffmpeg: no message"
cmp -s "$video" "$top/old.mp4" || fail "no ffmpeg: the video changed"
[ "$(ls "$frames")" = "$(cat "$top/ready")" ] || fail "no ffmpeg: the frames changed"
echo "no ffmpeg: a clear error, the video and its frames intact"
