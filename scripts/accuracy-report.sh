#!/usr/bin/env bash
# Regenerates the data and plots of docs/accuracy.md: the precision study on the default and
# the stiff sheet, and the stability sweeps (grid, mass, stiffness), in a Release build.
# Takes a few minutes on a 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j 2 --target weft-bench
bench=build/release/bench/weft_bench/weft-bench
out=docs/accuracy
mkdir -p "$out"
"$bench" precision --out "$out" | tee "$out/precision.log"
"$bench" stability --out "$out" | tee "$out/stability.log"
