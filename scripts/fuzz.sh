#!/usr/bin/env bash
# Fuzzes the scene loader and --set parsing with libFuzzer (clang, ASan + UBSan), seeded
# with assets/scenes and the inputs earlier runs found (fuzz/regressions).
#   scripts/fuzz.sh            a short run: 60 s (what CI does)
#   scripts/fuzz.sh 3600       a long run: one hour; new findings land in ./crash-* files
# Inputs that crash, hang (> 10 s) or use more than 2 GiB fail the run.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}

packages=(clang libclang-rt-14-dev)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "weft: installing missing packages: ${missing[*]}"
  sudo=(); [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
scripts/setup.sh

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j 2 --target weft_scene_fuzzer
fuzzer=build/fuzz/fuzz/weft_scene_fuzzer
# Every earlier finding first: each must now load or be refused cleanly.
"$fuzzer" -rss_limit_mb=2048 -timeout=10 fuzz/regressions/*
corpus=build/fuzz/corpus
mkdir -p "$corpus"
cp -n assets/scenes/*.toml "$corpus"/
"$fuzzer" "$corpus" -dict=fuzz/dictionary/scene.dict -max_total_time="$seconds" \
  -rss_limit_mb=2048 -timeout=10 -max_len=4096 -print_final_stats=1 2>&1 | tail -n 12
