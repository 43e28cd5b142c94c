#!/usr/bin/env bash
# End-to-end test of the real weft window under Xvfb, driven by xdotool:
#   1. the camera keys change the view (two F12 screenshots differ), and the wheel over the
#      panel does not;
#   2. space + mouse on the cloth pulls the cloth where the mouse went (state dumped when
#      the window closes, while still held, against an undisturbed run);
#   3. space + mouse on empty background leaves the cloth as an undisturbed run leaves it;
#   4. side by side (--compare rk4) one drag moves both runs' columns, and the session it
#      recorded (--record) replays headless to the same state bit for bit;
#   5. what the window says, read off window screenshots (Shift+F12): a saved screenshot is
#      said in the success colour, a divergence in the problem colour and wrapped beside the
#      panel, and a red REC shows while recording;
#   6. the panel and the view share the window: at 800x600 and 1280x720 the view (the cloth
#      with it) is shown whole beside the panel, none of it under the panel;
#   7. a refused edit (-5 typed into a stiffness) is said under that slider, whole;
#   8. the panel's pause and step buttons pause and step the run, and its plots (energy,
#      largest stretch, ms per frame) hold still while paused;
#   9. a 2048 x 2048 grid applied in the panel is refused, said whole under Apply at the
#      panel's foot, and the sheet runs on as it was;
#  10. the hint on the view shows until the first pull, F9 captures frames into the captures
#      folder, and nothing is written into the folder weft was started from.
# Usage: window_e2e_test.sh WEFT PNG_DIFF SOURCE_DIR PNG_COLOUR_COUNT
set -uo pipefail
weft=$(realpath "$1")
png_diff=$(realpath "$2")
scene=$(realpath "$3")/tests/app/e2e_sheet.toml
png_colour_count=$(realpath "$4")
for tool in Xvfb xdotool; do
  command -v "$tool" >/dev/null || { echo "FAIL: $tool is missing (scripts/setup.sh installs it)"; exit 1; }
done
work=$(mktemp -d)
cleanup() {
  [ -n "${xvfb_pid:-}" ] && kill "$xvfb_pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
# An X server on a display it picks itself: with -displayfd, Xvfb takes a display no other
# server holds (a lock file, a socket file or an abstract socket) and writes its number only
# once it accepts connections, so weft never starts against a server that is not there yet.
# -noreset: by default the server resets when its last client leaves, and a weft started
# while it resets finds no display.
Xvfb -displayfd 3 -noreset -screen 0 1400x900x24 -nolisten tcp 3>"$work/display" >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
until [ -s "$work/display" ]; do
  kill -0 "$xvfb_pid" 2>/dev/null || { echo "FAIL: Xvfb exited before it took a display"; cat "$work/xvfb.log"; exit 1; }
  sleep 0.05
done
display=":$(head -1 "$work/display")"
export DISPLAY=$display
failures=0
passes=0
check() { if "$@"; then passes=$((passes + 1)); else echo "FAIL: $*"; failures=$((failures + 1)); fi; }

# The test waits on the window's state, not on the clock: weft rewrites WEFT_WINDOW_STATE
# after every frame it draws (src/app/window_state_file.h), and these poll it.
window_value() { awk -v key="$1" '$1 == key { print $2 }' "$work/$weft_name/window_state" 2>/dev/null; }
# wait_until WHAT TEST...: polls until TEST holds. The window exiting first is a failure; a
# window that never gets there is a hang, which ctest's timeout ends.
wait_until() {
  local what=$1
  shift
  until "$@"; do
    if ! kill -0 "$weft_pid" 2>/dev/null; then
      echo "FAIL: the window exited before $what"; failures=$((failures + 1)); return 1
    fi
    sleep 0.05
  done
}
window_found() {
  window=$(xdotool search --name "weft - e2e sheet" 2>/dev/null | head -1)
  [ -n "$window" ]
}
frames_at_least() { [ "$(window_value frames)" -ge "$1" ] 2>/dev/null; }
time_at_least() { awk -v t="$(window_value time)" -v s="$1" 'BEGIN { exit !(t != "" && t >= s) }'; }
settled() {  # 2.5 s of simulated time, or paused (parameters no step can hold pause the run)
  awk -v t="$(window_value time)" -v p="$(window_value paused)" 'BEGIN { exit !(t >= 2.5 || p == 1) }'
}
# wait_frames N: until the window has drawn N more frames. A frame handles every event sent
# before it began, so two frames after an input the window has answered it and drawn the
# answer.
wait_frames() {
  local now
  now=$(window_value frames)
  wait_until "drawing $1 more frames" frames_at_least $((${now:-0} + $1))
}
# wait_sim_seconds S: until the main run's simulated time has gone on S seconds.
wait_sim_seconds() {
  local start
  start=$(window_value time)
  wait_until "$1 s more of simulated time" time_at_least "$(awk -v a="${start:-0}" -v s="$1" 'BEGIN { printf "%.17g", a + s }')"
}

# Starts weft in $work/$1 (further arguments go to weft), its captures folder (screenshots,
# sessions, frames) $work/$1/captures, waits for its window; sets $weft_pid, $weft_name and
# $window.
start_weft() {
  local name=$1
  weft_name=$name
  shift
  mkdir -p "$work/$name"
  (cd "$work/$name" && WEFT_CAPTURES="$work/$name/captures" WEFT_WINDOW_STATE="$work/$name/window_state" exec "$weft" "$scene" --size 800x600 --dump "$work/$name/state.csv" "$@" >"$work/$name/out.log" 2>&1) &
  weft_pid=$!
  window=""
  wait_until "its window appeared" window_found || { cat "$work/$name/out.log"; exit 1; }
  wait_until "the sheet settled" settled
}
# Quits with Escape; weft must exit with status 0 (under ASan: no leak, no error at exit).
quit_weft() {
  xdotool key --window "$window" Escape
  for _ in $(seq 100); do kill -0 "$weft_pid" 2>/dev/null || break; sleep 0.1; done
  wait "$weft_pid"
  local status=$?
  [ "$status" -eq 0 ] || { echo "weft exited with status $status:"; tail -20 "$work/$weft_name/out.log"; }
  check test "$status" -eq 0
}
# The window is 800 x 600: the panel takes its left 300 px (src/app/screen_layout.cpp), the
# view the 500 x 600 beside it, with the sheet's centre at the view's centre, window pixel
# (550, 300) (the camera's target is 2.5 cm above it). The camera looks straight at the sheet
# from 1.6 m with a 50° vertical field of view: about 402 pixels per metre at the sheet.
panel_right=300
# x of particle (row, col) from a dump
particle_x() { awk -F, -v r="$2" -v c="$3" 'NR > 1 && $1 == r && $2 == c { print $3 }' "$1"; }

# --- 1. an undisturbed run, and the camera keys ---------------------------------------------
start_weft rest
xdotool key --window "$window" F12
wait_frames 3
# The wheel turned as the cursor arrives over the panel scrolls the panel only: the view is
# as it was (the first wheel over the panel of a fresh window used to zoom the view too).
xdotool mousemove --window "$window" 150 300 click 5 click 5 click 5
wait_frames 3
xdotool key --window "$window" F12
wait_frames 3
xdotool keydown --window "$window" w; wait_frames 30; xdotool keyup --window "$window" w
xdotool keydown --window "$window" Left; wait_frames 20; xdotool keyup --window "$window" Left
wait_frames 3
xdotool key --window "$window" F12
wait_frames 3
xdotool key --window "$window" c      # back to the scene's camera before quitting
quit_weft
shots=("$work"/rest/captures/weft-screenshot-*.png)
check test "${#shots[@]}" -eq 3
wheeled=$("$png_diff" "${shots[0]}" "${shots[1]}")
echo "the wheel over the panel changed $wheeled of the view's pixels"
check awk -v f="$wheeled" 'BEGIN { exit !(f < 0.01) }'
changed=$("$png_diff" "${shots[1]}" "${shots[2]}")
echo "camera keys changed $changed of the pixels"
check awk -v f="$changed" 'BEGIN { exit !(f > 0.05) }'
check test -s "$work/rest/state.csv"

# --- 2. space + mouse on the cloth pulls it ---------------------------------------------------
# Particle (12, 7) is at (-0.025, -0.2) m: pixel (540, 390). The mouse drags it 0.5 m to the
# right.
start_weft drag
xdotool mousemove --window "$window" 540 390
wait_frames 2
xdotool keydown --window "$window" space
for step in $(seq 1 10); do xdotool mousemove --window "$window" $((540 + 20 * step)) 390; wait_frames 2; done
wait_sim_seconds 1.0
quit_weft   # still holding: the dump shows the cloth where the hand holds it
xdotool keyup space
rest_x=$(particle_x "$work/rest/state.csv" 12 7)
drag_x=$(particle_x "$work/drag/state.csv" 12 7)
echo "dragged particle x: at rest $rest_x m, after the drag $drag_x m"
check awk -v a="$rest_x" -v b="$drag_x" 'BEGIN { exit !(b - a > 0.15) }'

# --- 3. space + mouse on the background grabs nothing -----------------------------------------
# The sheet spans x = 399 to 701: x = 760 is right of it.
start_weft miss
xdotool mousemove --window "$window" 760 120
wait_frames 2
xdotool keydown --window "$window" space
for step in $(seq 1 10); do xdotool mousemove --window "$window" 760 $((120 + 30 * step)); wait_frames 2; done
wait_sim_seconds 0.5
xdotool keyup --window "$window" space
quit_weft
largest=$(paste -d, <(tail -n +2 "$work/rest/state.csv") <(tail -n +2 "$work/miss/state.csv") |
  awk -F, '{ for (k = 3; k <= 5; k++) { d = $k - $(k + 8); if (d < 0) d = -d; if (d > m) m = d } } END { print m + 0 }')
echo "missed drag: largest difference from the undisturbed run $largest m"
check awk -v d="$largest" 'BEGIN { exit !(d < 0.002) }'

# --- 4. side by side, recorded, replayed ------------------------------------------------------
# The view beside the panel splits into two columns of 250 x 600 (not the window, half of which
# the panel covers): the sheet's centre is at window pixel (425, 300) in the left one (the main
# run, symplectic Euler) and (675, 300) in the right one (RK4), each column showing the middle
# 250 px of its sheet. The drag starts on the right copy.
start_weft side --compare rk4 --record "$work/side/session.toml"
xdotool key --window "$window" F12
wait_frames 3
xdotool mousemove --window "$window" 665 380
wait_frames 2
xdotool keydown --window "$window" space
for step in $(seq 1 10); do xdotool mousemove --window "$window" $((665 + 10 * step)) 380; wait_frames 2; done
wait_sim_seconds 0.8
xdotool key --window "$window" F12
wait_frames 3
xdotool keyup --window "$window" space
wait_frames 3
quit_weft
shots=("$work"/side/captures/weft-screenshot-*.png)
check test "${#shots[@]}" -eq 2
left=$("$png_diff" "${shots[0]}" "${shots[1]}" 0 250)
right=$("$png_diff" "${shots[0]}" "${shots[1]}" 250 500)
echo "side by side: the drag changed $left of the main run's column and $right of the copy's"
check awk -v f="$left" 'BEGIN { exit !(f > 0.01) }'
check awk -v f="$right" 'BEGIN { exit !(f > 0.01) }'
check test -s "$work/side/session.toml"
replay_output=$("$weft" --headless --replay "$work/side/session.toml" --dump "$work/side/replayed.csv")
replay_status=$?
echo "$replay_output"
check test "$replay_status" -eq 0
check grep -q "matches the recording" <<<"$replay_output"
check cmp -s "$work/side/state.csv" "$work/side/replayed.csv"

# --- a hard drag at one implicit Euler step a frame -------------------------------------------
# The hand's particles are constraints inside the implicit system (src/sim/interaction/grab.h): a pull
# away from the pinned top row and back past it, faster than the cloth can follow, must not
# diverge (no rollback, so dt is never halved). Particle (1, 1) is at (-0.325, 0.35) m:
# pixel (419, 169), one spacing from a pin, so the hand soon pulls a spring at it past the
# grip's 3 rest lengths and the cloth slips from the hand instead of stretching on. The hand
# sweeps the view beside the panel.
start_weft implicit --set solver.integrator=implicit-euler --set solver.dt=0.016666666666666666 \
  --set springs.bend.enabled=true
xdotool mousemove --window "$window" 419 172
wait_frames 2
xdotool keydown --window "$window" space
for round in 1 2 3; do
  for step in $(seq 1 8); do xdotool mousemove --window "$window" $((419 + 45 * step)) $((172 + 50 * step)); wait_frames 1; done
  for step in $(seq 1 8); do xdotool mousemove --window "$window" $((779 - 55 * step)) $((572 - 70 * step)); wait_frames 1; done
done
xdotool mousemove --window "$window" 700 550
wait_sim_seconds 1.0
quit_weft   # still holding, far from the pins
xdotool keyup space
implicit_rest_x=$(particle_x "$work/rest/state.csv" 1 1)
implicit_held_x=$(particle_x "$work/implicit/state.csv" 1 1)
echo "implicit Euler, hard drag: particle (1, 1) x at rest $implicit_rest_x m, held $implicit_held_x m"
check test "$(grep -c "diverged" "$work/implicit/out.log")" -eq 0
check awk -F, 'NR > 1 { for (i = 3; i <= 8; ++i) if ($i != $i + 0 || $i > 10 || $i < -10) exit 1 }' \
  "$work/implicit/state.csv"

# --- 5. what the window says ----------------------------------------------------------------
# The status lines' colours (src/app/status_overlay.cpp), as Dear ImGui writes them in bytes.
success_green="115 230 115"
problem_orange="255 128 77"
recording_red="255 64 64"
# The status lines belong in the view, right of the panel. They sit at the bottom, below the
# cloth (whose shading could match a colour): rows 480 to 600 are read.
# shoot_window NAME: the window as shown, panel and status lines included (Shift+F12), by the
# run in $work/NAME; the image's path in $window_shot.
shoot_window() {
  xdotool key --window "$window" shift+F12
  wait_frames 3
  window_shot=$(ls "$work/$1"/captures/weft-screenshot-*.png | tail -1)
}
# pixels IMAGE "R G B" X0 X1: pixels of that colour in those columns of rows 480 to 600.
pixels() { "$png_colour_count" "$1" $2 "$3" "$4" 480 600; }

# A screenshot (F12) is news of success: green, not the problem colour.
start_weft say
xdotool key --window "$window" F12
wait_frames 2
shoot_window say
quit_weft
saved_green=$(pixels "$window_shot" "$success_green" $panel_right 800)
saved_orange=$(pixels "$window_shot" "$problem_orange" 0 800)
saved_rec=$(pixels "$window_shot" "$recording_red" 0 800)
echo "'saved ...': $saved_green success-green pixels, $saved_orange problem-orange, $saved_rec REC-red"
check test "$saved_green" -gt 100
check test "$saved_orange" -eq 0
check test "$saved_rec" -eq 0   # not recording: no REC

# Hopeless parameters diverge every few steps; the message names a particle and is wider
# than the window. It must wrap beside the panel: none of it over the panel, none cut at the
# window's right edge (its last 8 columns stay clear).
start_weft diverge --set springs.structural.stiffness=1e300 --set cloth.particle_mass=1e-300
shoot_window diverge
quit_weft
beside=$(pixels "$window_shot" "$problem_orange" $panel_right 792)
over_panel=$(pixels "$window_shot" "$problem_orange" 0 $panel_right)
at_edge=$(pixels "$window_shot" "$problem_orange" 792 800)
echo "divergence message: $beside problem-orange pixels beside the panel, $over_panel over it, $at_edge at the right edge"
check test "$beside" -gt 300
check test "$over_panel" -eq 0
check test "$at_edge" -eq 0
check grep -q "no step above" "$work/diverge/out.log"

# Recording (--record, or F5): a red REC beside the panel.
start_weft record --record "$work/record/session.toml"
shoot_window record
quit_weft
rec=$(pixels "$window_shot" "$recording_red" $panel_right 800)
echo "recording: $rec REC-red pixels beside the panel"
check test "$rec" -gt 20

# --- 6. the panel and the view share the window --------------------------------------------
# At each size the issue names, the view's screenshot (F12) is as wide as the window less the
# panel (300 px at 800, 30 % = 384 px at 1280), and the window's screenshot (Shift+F12) shows
# it whole right of the panel: every pixel of the cloth is seen, none is under the panel.
# The top and bottom 60 rows are left out: the hint on the view (section 10) and the status
# lines (the screenshot's "saved ..." message) are drawn there.
png_width() { od -An -tu1 -j16 -N4 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4 }'; }
for size in 800x600:300 1280x720:384; do
  window_width=${size%%x*}
  panel_width=${size##*:}
  window_height=${size%%:*}
  window_height=${window_height#*x}
  name=fit-${size%%:*}
  start_weft "$name" --size "${size%%:*}"
  xdotool key --window "$window" F12
  wait_frames 3
  view_shot=$(ls "$work/$name"/captures/weft-screenshot-*.png | tail -1)
  shoot_window "$name"
  quit_weft
  view_width=$(png_width "$view_shot")
  shown=$("$png_diff" "$view_shot" "$window_shot" 0 "$view_width" "$panel_width" 60 $((window_height - 60)))
  echo "${size%%:*}: the view is $view_width px wide beside a $panel_width px panel; $shown of it differs from the window's pixels there"
  check test "$view_width" -eq $((window_width - panel_width))
  check awk -v f="$shown" 'BEGIN { exit !(f < 0.05) }'
done

# --- 7. a refused edit is said under its control ---------------------------------------------
# "materials" opens (its header at y = 390, under the statistics, their three plots and the
# solver); Ctrl+click on the structural stiffness slider (its first stiffness, at y = 430)
# types a value; -5 is refused. The refusal must be said right under the slider (rows 438 to
# 478), whole, inside the panel, and stay there (it used to sit at the panel's foot, cut off,
# out of sight) until the next edit, 700, which is taken.
refusal_red="255 102 102"
# type_into_slider X Y TEXT: Ctrl+click at (X, Y) and type TEXT, through the X server's own
# input (the slider ignores clicks sent to the window alone). Each key and button is held
# for two frames: Dear ImGui 1.86 reads keys and buttons once a frame, and one pressed and let
# go within a frame is lost. Text goes a character every two frames.
hold() { xdotool "$1"down "$2"; wait_frames 2; xdotool "$1"up "$2"; wait_frames 2; }
type_text() {
  local i
  for ((i = 0; i < ${#1}; i++)); do xdotool type -- "${1:i:1}"; wait_frames 2; done
}
type_into_slider() {
  xdotool windowfocus --sync "$window"
  xdotool mousemove --window "$window" "$1" "$2"
  wait_frames 2
  xdotool keydown ctrl
  wait_frames 2
  hold mouse 1
  xdotool keyup ctrl
  wait_frames 3
  hold key ctrl+a   # the slider's text is selected already; this makes sure
  type_text "$3"
  hold key Return
  wait_frames 3
}
refusal_pixels() { "$png_colour_count" "$window_shot" $refusal_red "$1" "$2" 438 478; }
click_at() {
  xdotool mousemove --window "$window" "$1" "$2"
  wait_frames 2
  hold mouse 1
  wait_frames 3
}
start_weft refuse
xdotool windowfocus --sync "$window"
click_at 100 390   # open "materials"
type_into_slider 60 430 -5
shoot_window refuse
under_slider=$(refusal_pixels 0 $panel_right)
beyond_panel=$(refusal_pixels $panel_right 800)
wait_frames 180   # 3 s or more: frames come at most at the display's 60 Hz
shoot_window refuse
later=$(refusal_pixels 0 $panel_right)
type_into_slider 60 430 700
shoot_window refuse
after_next_edit=$(refusal_pixels 0 800)
echo "refused -5: $under_slider refusal-red pixels under the slider, $beyond_panel beyond the panel; 3 s later $later; after the next edit $after_next_edit"
check test "$under_slider" -gt 300
check test "$beyond_panel" -eq 0
check test "$later" -eq "$under_slider"
check test "$after_next_edit" -eq 0

# --- 8. pause and step buttons; the plots hold still while paused ----------------------------
# In the same window. The three plots and their labels fill the panel's rows 135 to 292; a
# frame that steps
# adds a sample to each (the ms-per-frame one is never flat), so they move while running,
# hold still while paused (the energy plot used to scroll), and move once for one step.
# The buttons sit at the panel's top: pause at (42, 50), step at (117, 50).
plots_changed() { "$png_diff" "$1" "$2" 8 280 8 135 292; }
shoot_window refuse; running_a=$window_shot
shoot_window refuse; running_b=$window_shot
click_at 42 50   # pause (P)
shoot_window refuse; paused_a=$window_shot
wait_frames 30
shoot_window refuse; paused_b=$window_shot
click_at 117 50  # step (N)
shoot_window refuse; stepped=$window_shot
quit_weft
running=$(plots_changed "$running_a" "$running_b")
paused=$(plots_changed "$paused_a" "$paused_b")
one_step=$(plots_changed "$paused_b" "$stepped")
echo "plots: $running of their pixels changed between two shots running, $paused over 30 frames paused, $one_step for one step"
check awk -v f="$running" 'BEGIN { exit !(f > 0.01) }'
check awk -v f="$paused" 'BEGIN { exit !(f == 0) }'
check awk -v f="$one_step" 'BEGIN { exit !(f > 0.001) }'

# --- 9. a grid the window cannot step is refused, and said whole -----------------------------
# The panel used to build a 2048 x 2048 grid (about 10 s and 1.7 GB, the window frozen).
# It is refused before anything is built (src/app/grid_edit.h). With "solver" folded (its
# header at y = 304) the grid section opens under its header (y = 350): rows at y = 373,
# cols at y = 396, and with 2048 x 2048 typed (the limit's warning wrapping to two lines)
# Apply at y = 558, so close to the window's foot that its refusal, five lines in
# the 300 px panel, would be cut off after its first: the panel must scroll it whole into
# sight. Then a dump of the running sheet when the window closes still holds its 16 x 16
# particles.
type_into_field() {
  xdotool mousemove --window "$window" "$1" "$2"
  wait_frames 2
  hold mouse 1
  wait_frames 2
  hold key ctrl+a
  type_text "$3"
  hold key Return
  wait_frames 3
}
start_weft grid
xdotool windowfocus --sync "$window"
click_at 100 304   # fold "solver"
click_at 100 350   # open "grid (rebuilt on apply)"
type_into_field 50 373 2048
type_into_field 50 396 2048
click_at 100 558   # apply
xdotool mousemove --window "$window" 550 300
wait_frames 3
shots_before=$(ls "$work/grid"/captures/weft-screenshot-*.png 2>/dev/null | wc -l)
shoot_window grid
shots_after=$(ls "$work/grid"/captures/weft-screenshot-*.png | wc -l)
quit_weft
refusal_lines=$("$png_colour_count" --lines "$window_shot" $refusal_red 0 $panel_right)
refusal_beyond=$("$png_colour_count" "$window_shot" $refusal_red $panel_right 800)
particles=$(($(wc -l <"$work/grid/state.csv") - 1))
echo "a 2048 x 2048 grid applied: its refusal shows $refusal_lines lines in the panel, $refusal_beyond pixels beyond it; the sheet has $particles particles"
check test "$shots_after" -eq $((shots_before + 1))   # the window still answers
check test "$refusal_lines" -eq 5
check test "$refusal_beyond" -eq 0
check test "$particles" -eq 256

# --- 10. the hint on the view; frames out (F9); nothing in the working folder ---------------
# Until the hand is first used, a line at the top of the view says how (white text, rows 8 to
# 45 beside the panel); a pull takes it away. F9 starts and stops a capture: one PNG of the
# view (500 x 600) per 1/30 s of simulated time, in a new folder of the captures folder.
hint_pixels() { "$png_colour_count" "$window_shot" 255 255 255 $panel_right 800 8 45; }
start_weft hint
shoot_window hint
hint_before=$(hint_pixels)
xdotool key --window "$window" F9
wait_sim_seconds 0.5
xdotool key --window "$window" F9
xdotool mousemove --window "$window" 540 390
wait_frames 2
xdotool keydown --window "$window" space
for step in $(seq 1 5); do xdotool mousemove --window "$window" $((540 + 20 * step)) 390; wait_frames 2; done
xdotool keyup --window "$window" space
wait_frames 3
shoot_window hint
hint_after=$(hint_pixels)
quit_weft
frames=("$work"/hint/captures/weft-frames-0001/frame-*.png)
in_working_folders=$(ls "$work"/*/*.png 2>/dev/null | wc -l)
echo "hint: $hint_before white pixels before the first pull, $hint_after after; F9 for 0.5 s of simulated time: ${#frames[@]} frames, $(png_width "${frames[0]}") px wide; $in_working_folders PNG files in the working folders"
check test "$hint_before" -gt 200
check test "$hint_after" -eq 0
# Half a second of simulated time between the two F9s, less the frames before the first was
# handled: 12 frames or more at 30 a simulated second, numbered without a gap from 0.
last_frame=$(printf '%s/hint/captures/weft-frames-0001/frame-%05d.png' "$work" $((${#frames[@]} - 1)))
check test "${#frames[@]}" -ge 12
check test -e "$last_frame"
check test "$(png_width "${frames[0]}")" -eq 500
check test "$in_working_folders" -eq 0

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
