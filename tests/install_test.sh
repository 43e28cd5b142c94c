#!/usr/bin/env bash
# cmake --install: weft and weft-bench land in PREFIX/bin and the shipped scenes in
# PREFIX/share/weft/scenes, and the installed weft finds its default scene there — in the
# installed folder, not the source tree (the installed default is swapped for a 3x3 sheet,
# which the dump must show), also after the whole prefix is moved.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR VERSION
set -uo pipefail
build=$1
source_dir=$2
version=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
source "$(dirname "$0")/cli_expect.sh"

prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1
check "cmake --install succeeds" test $? -eq 0
check "weft installed" test -x "$prefix/bin/weft"
check "weft-bench installed" test -x "$prefix/bin/weft-bench"
for scene in "$source_dir"/assets/scenes/*.toml; do
  check "$(basename "$scene") installed" cmp -s "$scene" "$prefix/share/weft/scenes/$(basename "$scene")"
done
check "the recorded session installed" test -s "$prefix/share/weft/sessions/fling.toml"

program=$prefix/bin/weft
expect 0 quiet -- --version
check "installed weft --version" test "$(cat "$work/out")" = "weft $version"
# The installed default scene, unchanged: the 24x24 sheet.
expect 0 quiet -- --headless --steps 20 --dump "$work/default.csv"
check "default scene: 24x24 particles" test "$(tail -n +2 "$work/default.csv" | wc -l)" -eq 576

# The installed default swapped for a 3x3 sheet: the installed weft reads that one.
sed -i 's/^rows = 24/rows = 3/; s/^cols = 24/cols = 3/' "$prefix/share/weft/scenes/hanging_sheet.toml"
expect 0 quiet -- --headless --steps 20 --dump "$work/swapped.csv"
check "reads the installed default scene" test "$(tail -n +2 "$work/swapped.csv" | wc -l)" -eq 9

# Moved elsewhere, the install still finds its scenes beside itself.
mv "$prefix" "$work/moved"
program=$work/moved/bin/weft
expect 0 quiet -- --headless --steps 20 --dump "$work/moved.csv"
check "a moved install reads its own scenes" test "$(tail -n +2 "$work/moved.csv" | wc -l)" -eq 9

# The installed weft-bench runs a study on its default scenes (tiny: 4x4, 2 ms).
program=$work/moved/bin/weft-bench
expect 0 quiet -- --version
expect 0 quiet -- invariants --set cloth.rows=4 --set cloth.cols=4 --duration 0.002 --repeats 1 \
  --out "$work/inv"
check "weft-bench wrote its study" test -s "$work/inv/invariants_tearing_sheet.csv"

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
