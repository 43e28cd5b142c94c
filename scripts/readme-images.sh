#!/usr/bin/env bash
# Redraws the README's headless images (docs/images) with the commands the README gives for
# them, into OUT_DIR (default docs/images), with WEFT (default build/release/src/app/weft).
# The window's own screenshots (demo-window.png at 1280x720, demo-window-800x600.png) are
# taken by hand in the window (Shift+F12 under Xvfb, default scene, about 5 s in; the
# 800x600 one with the help card open, H).
# tests/readme_images_test.sh runs it into a scratch folder and compares.
usage="scripts/readme-images.sh [OUT_DIR]"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images}
weft=${WEFT:-build/release/src/app/weft}
scenes=assets/scenes
mkdir -p "$out"
"$weft" --headless "$scenes/hanging_sheet.toml" --steps 2000 --size 1280x720 \
  --screenshot "$out/hanging-sheet-half-second.png"
"$weft" --headless "$scenes/hanging_sheet.toml" --steps 2000 --size 1280x720 \
  --set camera.position=[1.9,0.2,-1.2] --set camera.target=[0,-0.1,-0.1] \
  --screenshot "$out/hanging-sheet-half-second-back.png"
# Each scene 4 s in: the steps are 4 s over the scene's own dt.
for scene_steps in sheet_on_sphere:10000 tablecloth:10000 drape_self_collision:10000 \
  self_fold:10000 round_tablecloth:10000 flag_with_hole:26667 skirt:10000; do
  scene=${scene_steps%%:*}
  "$weft" --headless "$scenes/$scene.toml" --steps "${scene_steps##*:}" --size 960x540 \
    --screenshot "$out/scene-$scene.png"
done
"$weft" --headless "$scenes/slope.toml" --steps 5000 --size 960x540 \
  --screenshot "$out/scene-slope.png"
"$weft" --headless --replay assets/sessions/tear.toml --size 960x540 \
  --screenshot "$out/torn-sheet.png" >/dev/null
"$weft" --headless --replay assets/sessions/tear.toml --compare rk4 --size 1280x540 \
  --screenshot "$out/side-by-side.png" >/dev/null
# The animation at the README's top: a recorded drag that tears the sheet, one frame per
# 1/15 s, made into a GIF by scripts/make-video.sh (with ffmpeg; skipped without it, which
# that script would install).
if command -v ffmpeg >/dev/null; then
  frames=$(mktemp -d)
  "$weft" --headless --replay assets/sessions/drag-and-tear.toml --frames "$frames" --fps 15 \
    --size 480x270 >/dev/null
  scripts/make-video.sh "$frames" "$out/drag-and-tear.gif" 15 >/dev/null
  rm -rf "$frames"
else
  echo "readme-images.sh: skipped drag-and-tear.gif: ffmpeg is missing (scripts/make-video.sh installs it)"
fi
