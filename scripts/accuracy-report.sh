#!/usr/bin/env bash
# Regenerates the data and plots of docs/accuracy.md: the precision study on the default and
# the stiff sheet, the invariant study on the tearing sheet and the sheet on a sphere (where
# a trajectory error means nothing), and the stability sweeps (grid, mass, stiffness), in a
# Release build. Takes a few minutes on a 2-core machine.
usage="scripts/accuracy-report.sh"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j 2 --target weft-bench
bench=build/release/bench/weft_bench/weft-bench
out=docs/accuracy
mkdir -p "$out"
"$bench" precision --out "$out" | tee "$out/precision.log"
# Runs shortened so the report stays within minutes: the tearing sheet for 0.5 s of wind (it
# swings out and back), the sheet on the sphere for 0.6 s (it lands at 0.23 s and drapes).
"$bench" invariants assets/scenes/tearing_sheet.toml --duration 0.5 --repeats 2 --out "$out" |
  tee "$out/invariants_tearing_sheet.log"
"$bench" invariants assets/scenes/sheet_on_sphere.toml --duration 0.6 --repeats 2 --out "$out" |
  tee "$out/invariants_sheet_on_sphere.log"
"$bench" stability --out "$out" | tee "$out/stability.log"
"$bench" replay assets/sessions/fling.toml --out "$out" | tee "$out/replay.log"
