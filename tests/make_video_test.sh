#!/usr/bin/env bash
# scripts/make-video.sh end to end: frames from weft --headless --frames become an MP4 and a
# GIF with one video frame per PNG, at the frames' size (the MP4 padded to even sides); a
# folder without frames and a name that is neither .mp4 nor .gif are refused with status 2.
# Usage: make_video_test.sh WEFT_BINARY SOURCE_DIR. Skipped (77) where ffmpeg is not installed:
# the script would install it, which a test run should not do.
set -uo pipefail
weft=$1
source_dir=$2
command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null || {
  echo "ffmpeg is not installed: skipped"
  exit 77
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
check() {
  local description=$1
  shift
  if "$@"; then passes=$((passes + 1)); else echo "FAIL: $description"; failures=$((failures + 1)); fi
}
# What ffprobe counts in a video: codec,width,height,frames.
probe() {
  ffprobe -v error -count_frames -select_streams v:0 \
    -show_entries stream=codec_name,width,height,nb_read_frames -of csv=p=0 "$1"
}

"$weft" --headless "$source_dir/assets/scenes/hanging_sheet.toml" --steps 1000 \
  --frames "$work/frames" --size 161x91 || exit 1
frames=$(ls "$work/frames" | wc -l)
check "0.25 s of frames at 30 a second: 8 PNG files" test "$frames" -eq 8
make_video="$source_dir/scripts/make-video.sh"
"$make_video" "$work/frames" "$work/clip.mp4" >/dev/null
check "the MP4: H.264, padded to even sides, a frame per PNG" \
  test "$(probe "$work/clip.mp4")" = "h264,162,92,$frames"
"$make_video" "$work/frames" "$work/clip.gif" 60 >/dev/null
check "the GIF: the frames' size, a frame per PNG" \
  test "$(probe "$work/clip.gif")" = "gif,161,91,$frames"
"$make_video" "$work/no-frames" "$work/x.mp4" 2>"$work/err"
check "a folder without frames: status 2" test $? -eq 2
check "... and says so" grep -q "^error: $work/no-frames: no frame-00000.png" "$work/err"
"$make_video" "$work/frames" "$work/x.avi" 2>"$work/err"
check "a name that is neither .mp4 nor .gif: status 2" test $? -eq 2
"$make_video" "$work/frames" "$work/x.gif" 0 2>"$work/err"
check "a rate of 0 frames a second: status 2" test $? -eq 2
check "nothing written for refused input" test ! -e "$work/x.mp4" -a ! -e "$work/x.avi" -a ! -e "$work/x.gif"

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
