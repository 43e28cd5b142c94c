#!/usr/bin/env bash
# Turns a folder of frames written by `weft --headless ... --frames DIR` into a video: an MP4
# (H.264, plays in browsers and players) or a GIF (its palette made from the frames). Installs
# ffmpeg when it is missing.
#   scripts/make-video.sh DIR OUT.mp4         at 30 frames a second, as --frames writes them
#   scripts/make-video.sh DIR OUT.gif 60      at the rate given to --fps
usage="scripts/make-video.sh DIR OUT.mp4|OUT.gif [FPS]"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail

fail() {
  echo "error: $1" >&2
  echo "usage: $usage" >&2
  exit 2
}
[ $# -ge 2 ] && [ $# -le 3 ] || fail "expects a folder of frames and a video file"
frames=$1 out=$2 fps=${3:-30}
[ -f "$frames/frame-00000.png" ] ||
  fail "$frames: no frame-00000.png (write frames with weft --headless ... --frames $frames)"
case "$out" in
  *.mp4 | *.gif) ;;
  *) fail "$out: the video's name must end in .mp4 or .gif" ;;
esac
[[ "$fps" =~ ^[0-9]+$ ]] && [ "$fps" -ge 1 ] && [ "$fps" -le 1000 ] ||
  fail "FPS: expects a whole number of frames a second from 1 to 1000, got '$fps'"

if ! command -v ffmpeg >/dev/null; then
  echo "weft: installing missing packages: ffmpeg"
  sudo=(); [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends ffmpeg
fi

input=(-framerate "$fps" -i "$frames/frame-%05d.png")
if [ "${out##*.}" = mp4 ]; then
  # H.264 in 4:2:0 wants even sides; faststart lets a browser play it while it loads.
  ffmpeg -y -loglevel error "${input[@]}" -vf "pad=ceil(iw/2)*2:ceil(ih/2)*2" \
    -c:v libx264 -pix_fmt yuv420p -crf 20 -movflags +faststart "$out"
else
  # One palette for the whole clip, from the colours that change between frames.
  ffmpeg -y -loglevel error "${input[@]}" \
    -vf "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer:bayer_scale=3" \
    "$out"
fi
echo "video: $out"
