#!/usr/bin/env bash
# End-to-end tests of the weft command line: exit statuses, messages on stderr and the dump
# format, as the design notes fix them. Usage: cli_test.sh WEFT_BINARY SOURCE_DIR VERSION
# (VERSION: the CMake project version, which --version must print).
set -uo pipefail
weft=$1
scenes=$2/assets/scenes
version=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0

program=$weft
source "$(dirname "$0")/../cli_expect.sh"

# The documented dump: header, then one row-major line per particle.
expect 0 quiet -- --headless "$scenes/hanging_sheet.toml" --steps 1000 --dump "$work/state.csv"
check "dump header" test "$(head -1 "$work/state.csv")" = "row,col,x,y,z,vx,vy,vz"
check "dump has 24x24 particle lines" test "$(tail -n +2 "$work/state.csv" | wc -l)" -eq 576
check "dump is row-major" test "$(sed -n '2p;3p;26p' "$work/state.csv" | cut -d, -f1,2 | tr '\n' ' ')" = "0,0 0,1 1,0 "
check "dump values are finite numbers" awk -F, 'NR > 1 { for (i = 3; i <= 8; i++) if ($i !~ /^-?[0-9.]+(e[-+][0-9]+)?$/) exit 1 }' "$work/state.csv"
# A pinned corner has not moved and has zero velocity.
check "pinned corner stays" test "$(sed -n 2p "$work/state.csv" | cut -d, -f6-8)" = "0,0,0"

# Exactly N steps: a run of 0 steps dumps the initial state.
expect 0 quiet -- --headless "$scenes/hanging_sheet.toml" --steps 0 --dump "$work/initial.csv"
check "zero steps keeps the initial velocities" awk -F, 'NR > 1 && ($6 != 0 || $7 != 0 || $8 != 0) { exit 1 }' "$work/initial.csv"

# No scene given: the default one, as in the window.
expect 0 quiet -- --headless --steps 0 --dump "$work/default.csv"
check "headless without a scene runs the default" cmp -s "$work/default.csv" "$work/initial.csv"

# Divergence: explicit Euler on the stiff sheet without damping blows up -> status 3.
expect 3 '^diverged at t=[0-9.]+: ' -- --headless "$scenes/stiff_sheet.toml" --steps 1000 \
  --set solver.integrator=explicit-euler --set springs.structural.damping=0
# Under the documented line, the same moment with its unit and place in the run (a bare
# "t=0.012000" left the reader to guess the unit).
check "the divergence time is said in seconds, with its step" \
  grep -Eq '^  that is [0-9.e+-]+ s of simulated time, in step [0-9]+ of 1000 \(dt [0-9.e+-]+ s\)$' "$work/err"
# The same sheet with its own (stable) settings does not.
expect 0 quiet -- --headless "$scenes/stiff_sheet.toml" --steps 1000

# Bad input: status 2 and `error: WHERE: WHAT`, before any simulation.
printf '[cloth]\nrows = 4\nstifness = 3\n' >"$work/typo.toml"
expect 2 "^error: $work/typo.toml:3:1: .*stifness" -- --headless "$work/typo.toml" --steps 1
printf '[springs.structural]\nstifness = 3\n' >"$work/typo2.toml"
expect 2 "did you mean 'stiffness'" -- --headless "$work/typo2.toml" --steps 1
printf '[solver]\ndt = -0.001\n' >"$work/negative_dt.toml"
expect 2 "^error: $work/negative_dt.toml:2:6: " -- --headless "$work/negative_dt.toml" --steps 1
expect 2 '^error: --set solver.dt: ' -- --headless "$scenes/hanging_sheet.toml" --steps 1 --set solver.dt=0
expect 2 '^error: --set cloth.particle_mass: ' -- --headless "$scenes/hanging_sheet.toml" --steps 1 --set cloth.particle_mass=-1
expect 2 '^error: --set cloth.rows: ' -- --headless "$scenes/hanging_sheet.toml" --steps 1 --set cloth.rows=0
expect 2 '^error: --set cloth.rowz: .*rows' -- --headless "$scenes/hanging_sheet.toml" --steps 1 --set cloth.rowz=3
expect 2 '^error: --set' -- --headless "$scenes/hanging_sheet.toml" --steps 1 --set nonsense
# A grid too large for memory is refused at once, not by an out-of-memory kill.
expect 2 '^error: --set cloth.(rows|cols): .*4194304' -- --headless "$scenes/hanging_sheet.toml" --steps 1 \
  --set cloth.rows=100000 --set cloth.cols=100000
expect 2 "^error: $work/missing.toml: " -- --headless "$work/missing.toml" --steps 1
# A mesh cloth runs headless, one dump line per vertex; a bad OBJ is refused with the OBJ's own
# file:line (its path made absolute, as the scene keeps it) and what is wrong.
printf 'v 0 0 0\nv 1 0 0\nv 1 -1 0\nv 0 -1 0\nf 1 4 3 2\n' >"$work/square.obj"
printf '[cloth]\nmesh = "square.obj"\npins = [1, 2]\n' >"$work/mesh.toml"
expect 0 quiet -- --headless "$work/mesh.toml" --steps 10 --dump "$work/mesh.csv"
check "a mesh dumps one line per vertex" test "$(tail -n +2 "$work/mesh.csv" | wc -l)" -eq 4
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' >"$work/bad.obj"
printf '[cloth]\nmesh = "bad.obj"\n' >"$work/bad_mesh.toml"
expect 2 "^error: $work/bad.obj:4: .*'4'" -- --headless "$work/bad_mesh.toml" --steps 10
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n' >"$work/fan.obj"
printf '[cloth]\nmesh = "fan.obj"\n' >"$work/fan.toml"
expect 2 "^error: $work/fan.obj:8: .*more than two faces" -- --headless "$work/fan.toml" --steps 10
# A directory reads as an empty file, which is the default scene: it must be refused, by the
# headless run, a replay, and the window before it opens one (no video driver here: a window
# that tried would fail with another message).
expect 2 "^error: $scenes: is a directory, not a scene file$" -- --headless "$scenes" --steps 10
expect 2 "^error: $scenes: is a directory, not a session file$" -- --headless --replay "$scenes"
program=env
expect 2 "^error: $scenes: is a directory, not a scene file$" -- -u DISPLAY -u WAYLAND_DISPLAY \
  SDL_VIDEODRIVER=no-such-driver "$weft" "$scenes"
program=$weft
expect 2 '^error: --steps: ' -- --headless "$scenes/hanging_sheet.toml" --steps many
expect 2 '^error: --headless: needs --steps' -- --headless "$scenes/hanging_sheet.toml"
expect 2 '^error: --frobnicate: unknown option' -- --frobnicate
expect 2 "^error: $work/nowhere/x.csv: cannot write" -- --headless "$scenes/hanging_sheet.toml" --steps 1 --dump "$work/nowhere/x.csv"
expect 0 quiet -- --help
check "--help prints the usage on stdout" grep -q '^  weft --help | --version$' "$work/out"
expect 0 quiet -- --version
check "--version prints the project version" test "$(cat "$work/out")" = "weft $version"

# Replaying a recording headless (the window records; here a recording is written by hand):
# status 0 when the state ends as recorded, 4 when it does not, 2 for a bad recording.
scene_text=$(sed 's/\\/\\\\/g; s/"/\\"/g' "$scenes/hanging_sheet.toml" | awk '{ printf "%s\\n", $0 }')
write_session() {  # write_session FILE HASH
  printf 'format = 1\nsteps = 300\nfinal_state_hash = "%s"\nscene = "%s"\n\n[[events]]\nstep = 100\nkind = "release-pins"\n' \
    "$2" "$scene_text" >"$1"
}
write_session "$work/session.toml" 0x0000000000000000
expect 4 quiet -- --headless --replay "$work/session.toml" --dump "$work/replayed.csv"
actual_hash=$(grep -o 'hash [0-9a-f]*' "$work/out" | cut -d' ' -f2)
check "a replay reports the hash it reached" test -n "$actual_hash"
check "the pins were released at step 100" awk -F, 'NR == 2 && $4 == 0.6 { exit 1 }' "$work/replayed.csv"
write_session "$work/session.toml" "0x$actual_hash"
expect 0 quiet -- --headless --replay "$work/session.toml"
check "a matching replay says so" grep -q "matches the recording" "$work/out"
# Counts in the words' right number: this recording has one event.
check "a replay counts its one event in the singular" grep -q "^replayed 300 steps and 1 event of " "$work/out"
printf 'format = 1\nsteps = 10\nfinal_state_hash = "0x00"\nscene = ""\n' >"$work/bad_session.toml"
expect 2 "^error: $work/bad_session.toml:3:" -- --headless --replay "$work/bad_session.toml"
expect 2 "^error: $work/none.toml: cannot read" -- --headless --replay "$work/none.toml"
expect 2 '^error: .*: --replay takes the scene from the recording' -- --headless --replay "$work/session.toml" "$scenes/hanging_sheet.toml"
expect 2 '^error: --set: ' -- --replay "$work/session.toml" --set solver.dt=0.001
expect 2 '^error: --compare: expects METHOD' -- --compare leapfrog
expect 2 '^error: --compare: expects a dt' -- --compare rk4=0
# Headless, --compare draws copies beside the main run in the screenshot and changes nothing
# else: the dump is the main run's, bit for bit the same as without them.
expect 0 quiet -- --headless "$scenes/hanging_sheet.toml" --steps 200 --dump "$work/alone.csv" \
  --screenshot "$work/alone.png" --size 320x180
expect 0 quiet -- --headless "$scenes/hanging_sheet.toml" --steps 200 --dump "$work/beside.csv" \
  --screenshot "$work/beside.png" --size 320x180 --compare rk4 --compare verlet=0.000125
check "copies leave the main run's dump as it was" cmp -s "$work/alone.csv" "$work/beside.csv"
check "copies are drawn in the screenshot" bash -c "test -s '$work/beside.png' && ! cmp -s '$work/alone.png' '$work/beside.png'"
expect 0 quiet -- --headless --replay "$work/session.toml" --compare rk4 --screenshot "$work/replay.png" --size 320x180
check "a replay beside a copy still matches" grep -q "matches the recording" "$work/out"
check "a replay beside a copy draws it" test -s "$work/replay.png"
expect 2 '^error: --record: only applies in the window' -- --headless "$scenes/hanging_sheet.toml" --steps 1 --record "$work/r.toml"

# --obj: the final cloth as Wavefront OBJ, its v lines the dump's positions digit for digit
# (both round-trip doubles), an f line per triangle of the intact 24² sheet.
expect 0 quiet -- --headless "$scenes/hanging_sheet.toml" --steps 200 --dump "$work/obj.csv" \
  --obj "$work/cloth.obj"
check "--obj: a v line per particle, at the dump's positions" \
  cmp -s <(awk -F, 'NR > 1 { print $3, $4, $5 }' "$work/obj.csv") \
  <(awk '$1 == "v" { print $2, $3, $4 }' "$work/cloth.obj")
check "--obj: two f lines a cell" test "$(grep -c '^f ' "$work/cloth.obj")" -eq $((2 * 23 * 23))
expect 2 "^error: $work/no/such/folder/cloth.obj: cannot write" -- --headless \
  "$scenes/hanging_sheet.toml" --steps 1 --obj "$work/no/such/folder/cloth.obj"
expect 2 '^error: --obj: only applies with --headless' -- "$scenes/hanging_sheet.toml" --obj x.obj

# --frames: one PNG per 1/30 s of simulated time from the start, so 0.1 s (400 steps of
# 0.25 ms) is frames 0 to 3; --fps 60 makes it 0 to 6. The sheet moves between them.
expect 0 quiet -- --headless "$scenes/hanging_sheet.toml" --steps 400 --frames "$work/frames" \
  --size 64x36
check "--frames: frame-00000.png to frame-00003.png" \
  test "$(ls "$work/frames" | tr '\n' ' ')" = "frame-00000.png frame-00001.png frame-00002.png frame-00003.png "
check "--frames: the sheet moves from frame to frame" \
  bash -c "! cmp -s '$work/frames/frame-00000.png' '$work/frames/frame-00003.png'"
expect 0 quiet -- --headless "$scenes/hanging_sheet.toml" --steps 400 --frames "$work/frames60" \
  --fps 60 --size 64x36
check "--frames --fps 60: seven frames" test "$(ls "$work/frames60" | wc -l)" -eq 7
# --profile: where the steps went, on stdout after the run, headless only.
expect 0 quiet -- --headless "$scenes/hanging_sheet.toml" --steps 100 --profile
check "--profile: says the steps it measured" grep -q '^profile: 100 steps of 0.25 ms' "$work/out"
check "--profile: a row per phase and the sum" \
  test "$(grep -cE '^  (integrate|strain limit|contacts and hand|tearing|guards|all) ' "$work/out")" -eq 6
expect 2 '^error: --profile: only applies with --headless' -- "$scenes/hanging_sheet.toml" --profile
# Every shipped session replays to the state hash it recorded (status 4 if not): the golden
# states of the integrators, the hand and tearing as they ship. A change of the numbers
# that is meant shows here, and the session's hash is renewed with it.
for session in "$scenes"/../sessions/*.toml; do
  # The 256² sessions take most of a minute each, longer under the sanitizers: they are the
  # real-time measurements' (docs/performance.md), replayed by hand.
  case "$(basename "$session")" in cloth_256_*) continue ;; esac
  # Under the sanitizers (the sanitize test preset sets WEFT_SANITIZED) the 128² implicit
  # sessions take most of a minute too; the same code runs there in shorter tests.
  if [ -n "${WEFT_SANITIZED:-}" ]; then
    case "$(basename "$session")" in cloth_128_*) continue ;; esac
  fi
  check "$(basename "$session") reproduces its recording" \
    bash -c "timeout 120 '$weft' --headless --replay '$session' 2>/dev/null | grep -q 'matches the recording'"
done
# A replay's frames: the shipped drag that tears, 4800 steps of 1 ms, at 15 a second is frames
# 0 to 72, the last the same picture as the replay's screenshot at the end.
expect 0 quiet -- --headless --replay "$scenes/../sessions/drag-and-tear.toml" \
  --frames "$work/replayed-frames" --fps 15 --size 64x36 --screenshot "$work/replayed-end.png"
check "--replay --frames: 73 frames" test "$(ls "$work/replayed-frames" | wc -l)" -eq 73
check "--replay --frames: the last frame is the end" \
  cmp -s "$work/replayed-frames/frame-00072.png" "$work/replayed-end.png"
expect 2 '^error: --fps: only applies with --frames' -- --headless "$scenes/hanging_sheet.toml" \
  --steps 1 --fps 60
expect 2 '^error: --fps: expects a whole number' -- --headless "$scenes/hanging_sheet.toml" \
  --steps 1 --frames "$work/f" --fps 0
expect 2 '^error: --frames: only applies with --headless' -- "$scenes/hanging_sheet.toml" \
  --frames "$work/f"
touch "$work/a-file"
expect 2 "^error: $work/a-file/frames: cannot make the frames' folder" -- --headless \
  "$scenes/hanging_sheet.toml" --steps 1 --frames "$work/a-file/frames"

# The window steps in real time: a dt it cannot step (one step in more than 100 ms) is refused
# before any window opens, in the scene and in a copy.
expect 2 "^error: $scenes/hanging_sheet.toml: solver.dt: at most 100 ms in the window" -- \
  "$scenes/hanging_sheet.toml" --set solver.dt=1e6
expect 2 '^error: --compare: solver.dt: at most 100 ms in the window' -- \
  "$scenes/hanging_sheet.toml" --compare rk4=0.5

# No display (over SSH, or DISPLAY unset): status 2 and what to do, never a window that is
# not there running on until it is killed (timeout's status would be 124).
env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER timeout 60 "$weft" \
  "$scenes/hanging_sheet.toml" >"$work/out" 2>"$work/err"
no_display_status=$?
check "no display: status 2 (got $no_display_status)" test "$no_display_status" -eq 2
check "no display: says so and what to do" \
  grep -qx "error: no display: set DISPLAY, or use --headless" "$work/err"

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
