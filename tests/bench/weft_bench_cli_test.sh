#!/usr/bin/env bash
# weft-bench's command line: bad numbers are refused with status 2 and `error: --OPTION: ...`
# (never silently replaced), tiny invariant and realtime studies write the documented CSV and
# plots, and every study answers --help.
# Usage: weft_bench_cli_test.sh WEFT_BENCH_BINARY SOURCE_DIR VERSION
# (VERSION: the CMake project version, which --version must print).
set -uo pipefail
bench=$1
scenes=$2/assets/scenes
version=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0

program=$bench
source "$(dirname "$0")/../cli_expect.sh"

# Help and version, as the design's command line promises: usage on stdout, status 0.
expect 0 quiet -- --help
for study in precision invariants stability throughput replay realtime; do
  check "--help names $study" grep -q "^  weft-bench $study " "$work/out"
done
expect 0 quiet -- --version
check "--version prints the project version" test "$(cat "$work/out")" = "weft-bench $version"
for study in precision invariants stability throughput replay realtime; do
  # Help wins over everything else on the line, even a value that would be refused.
  expect 0 quiet -- $study --help --out "$work/x"
  check "$study --help starts with its usage" test "$(sed -n 2p "$work/out" | awk '{ print $1, $2 }')" = "weft-bench $study"
  expect 0 quiet -- $study --repeats 0 -h
  expect 0 quiet -- $study --version
  check "$study --version prints the project version" test "$(cat "$work/out")" = "weft-bench $version"
done
expect 2 "^error: unknown study 'precisoin'" -- precisoin --help

# Strict numbers: the whole text, in range, or status 2 before anything runs.
for study in precision invariants; do
  expect 2 "^error: --repeats: 'abc' is not an integer" -- $study --repeats abc --out "$work/x"
  expect 2 "^error: --repeats: '3x' is not an integer" -- $study --repeats 3x --out "$work/x"
  expect 2 "^error: --repeats: '0' is out of range" -- $study --repeats 0 --out "$work/x"
  expect 2 "^error: --repeats: '-2' is out of range" -- $study --repeats -2 --out "$work/x"
  expect 2 "^error: --duration: '1x' is not a number" -- $study --duration 1x --out "$work/x"
  expect 2 "^error: --duration: '0' must be a finite number > 0" -- $study --duration 0 --out "$work/x"
  expect 2 "^error: --duration: 'nan' must be" -- $study --duration nan --out "$work/x"
  expect 2 "^error: --duration: '' is not a number" -- $study --duration "" --out "$work/x"
done
expect 2 "^error: --duration: '1e999' must be" -- stability --duration 1e999 --out "$work/x"
expect 2 "^error: unknown study 'precisoin'" -- precisoin
expect 2 "^error: unknown or incomplete option --repeats" -- invariants --repeats
# A directory is not a scene (it would read as the default one).
expect 2 "^error: $scenes: is a directory, not a scene file$" -- stability "$scenes" --out "$work/x"
check "nothing was written for refused input" test ! -e "$work/x"

# A tiny invariant study: 4x4 tearing sheet, 8 ms per run. One reference row, then six
# integrators x six steps, each row complete.
expect 0 quiet -- invariants "$scenes/tearing_sheet.toml" --set cloth.rows=4 --set cloth.cols=4 \
  --duration 0.008 --repeats 1 --out "$work/inv"
csv=$work/inv/invariants_tearing_sheet.csv
check "invariants CSV header" grep -q '^scene,integrator,dt_s,duration_s,steps,diverged,' "$csv"
check "reference + 36 rows" test "$(tail -n +2 "$csv" | wc -l)" -eq 37
check "every row has every column" awk -F, 'NR == 1 { n = NF } NF != n { exit 1 }' "$csv"
check "the reference row comes first" test "$(sed -n 2p "$csv" | cut -d, -f2)" = rk4-reference
for plot in strain energy sag; do
  check "plot $plot" test -s "$work/inv/invariants_tearing_sheet_$plot.png"
done

# precision sends a contact scene to the invariant study, and writes no trajectory errors.
expect 0 quiet -- precision "$scenes/sheet_on_sphere.toml" --set cloth.rows=3 --set cloth.cols=3 \
  --duration 0.004 --repeats 1 --out "$work/prec"
check "contact scene measured by invariants" test -s "$work/prec/invariants_sheet_on_sphere.csv"
check "no trajectory errors for it" test ! -e "$work/prec/precision.csv"

# --repeats 1 is one timed run per point (it used to take the median of no runs and crash). A
# 2x2 default sheet: six integrators x six steps, each with a measured time.
expect 0 quiet -- precision "$scenes/hanging_sheet.toml" --set cloth.rows=2 --set cloth.cols=2 \
  --repeats 1 --out "$work/prec1"
csv=$work/prec1/precision.csv
check "precision --repeats 1: 36 rows" test "$(tail -n +2 "$csv" | wc -l)" -eq 36
check "precision --repeats 1: every time is a number > 0" \
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "seconds_per_simulated_second") c = i }
           NR > 1 && !($c + 0 > 0) { exit 1 } END { if (!c) exit 1 }' "$csv"

# replay: a drag recorded in the window (assets/sessions/fling.toml), replayed by every
# integrator; the recorded one must end in the recorded state bit for bit.
expect 0 '' -- replay "$2/assets/sessions/fling.toml" --out "$work/replay"
csv=$work/replay/replay.csv
check "replay CSV header" grep -q '^integrator,recorded,matches_recording,recoveries,' "$csv"
check "one row per integrator" test "$(tail -n +2 "$csv" | wc -l)" -eq 6
check "the recorded integrator reproduces the recording" grep -q '^symplectic-euler,yes,yes,0,' "$csv"
# The step profile's columns: implicit Euler counts its CG iterations (column 21); the
# explicit methods have none.
check "replay CSV: the step profile's columns" \
  grep -q ',force_evaluations,cg_iterations,splits$' "$csv"
check "replay CSV: implicit Euler's iterations are counted, symplectic Euler's are 0" \
  awk -F, '$1 == "implicit-euler" { i = $21 } $1 == "symplectic-euler" { s = $21 }
           END { exit !(i > 0 && s == 0) }' "$csv"
expect 2 'error: .*missing.toml: cannot read' -- replay "$work/missing.toml" --out "$work/replay2"
expect 2 '^error: replay takes one recorded session' -- replay --out "$work/replay3"

# realtime: --help on stdout with status 0; bad numbers refused; a tiny run (an 8x8 sheet,
# three frames) writes one CSV row per method and setting, the summary and the plot.
expect 0 quiet -- realtime --help
check "realtime --help describes the study" grep -q 'weft-bench realtime' "$work/out"
expect 2 "^error: --max-run-seconds: '0' must be" -- realtime --max-run-seconds 0 --out "$work/x"
expect 2 "^error: --sizes: '2' is out of range" -- realtime --sizes 2 --out "$work/x"
expect 2 '^error: realtime takes one scene' -- realtime a.toml b.toml --out "$work/x"
check "nothing was written for refused input" test ! -e "$work/x"
expect 0 quiet -- realtime "$scenes/large_rubber_sheet.toml" --sizes 8 --duration 0.05 --out "$work/rt"
csv=$work/rt/realtime.csv
check "realtime CSV header" grep -q '^particles_per_side,particles,springs,method,setting,dt_s,' "$csv"
# The two weft-to-plain ratios (double and float springs), 1 + 1 + 3 + 4 + 1 method settings,
# the reference and a summary per method.
check "2 ratios + 10 settings + reference + 5 summaries" \
  test "$(tail -n +2 "$csv" | wc -l)" -eq 18
check "every row has every column" awk -F, 'NR == 1 { n = NF } NF != n { exit 1 }' "$csv"
check "four XPBD substep counts" test "$(grep -c ',XPBD float,[0-9]* substeps,' "$csv")" -eq 4
check "every setting ran to the end on the small sheet" \
  test "$(grep -c ',ok$' "$csv")" -eq 10
check "the output states the weft-to-plain-float ratio" grep -q 'the plain float step: [0-9.]* on' "$work/out"
check "realtime plot" test -s "$work/rt/realtime_8.png"

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
