#!/usr/bin/env bash
# Fuzzes the scene loader and --set parsing, then the session recordings that --replay reads
# (each replayed when small), then the OBJ reader and mesh builder (each small mesh stepped),
# with libFuzzer (clang, ASan + UBSan), seeded with assets/scenes, fuzz/sessions, fuzz/obj
# and the inputs earlier runs found (fuzz/regressions).
#   scripts/fuzz.sh            a short run: 60 s of scenes, 30 s each of sessions and OBJ
#                              files (what CI does)
#   scripts/fuzz.sh 3600       a long run: an hour, and half an hour each; findings land in
#                              ./crash-*
# Inputs that crash, hang (> 10 s) or use more than 2 GiB fail the run.
usage="scripts/fuzz.sh [SECONDS]"
source "$(dirname "$0")/help_or_version.sh"
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
cmake --build --preset fuzz -j 2 --target weft_scene_fuzzer weft_session_fuzzer \
  weft_obj_fuzzer
fuzzer=build/fuzz/fuzz/weft_scene_fuzzer
# Every earlier finding first: each must now load or be refused cleanly.
"$fuzzer" -rss_limit_mb=2048 -timeout=10 fuzz/regressions/*
corpus=build/fuzz/corpus
mkdir -p "$corpus"
cp -n assets/scenes/*.toml "$corpus"/
"$fuzzer" "$corpus" -dict=fuzz/dictionary/scene.dict -max_total_time="$seconds" \
  -rss_limit_mb=2048 -timeout=10 -max_len=4096 -print_final_stats=1 2>&1 | tail -n 12

session_fuzzer=build/fuzz/fuzz/weft_session_fuzzer
session_corpus=build/fuzz/session-corpus
mkdir -p "$session_corpus"
cp -n fuzz/sessions/*.toml "$session_corpus"/
"$session_fuzzer" "$session_corpus" -dict=fuzz/dictionary/scene.dict \
  -max_total_time=$((seconds / 2)) -rss_limit_mb=2048 -timeout=10 -max_len=8192 \
  -print_final_stats=1 2>&1 | tail -n 12

obj_fuzzer=build/fuzz/fuzz/weft_obj_fuzzer
obj_corpus=build/fuzz/obj-corpus
mkdir -p "$obj_corpus"
cp -n fuzz/obj/*.obj "$obj_corpus"/
"$obj_fuzzer" "$obj_corpus" -dict=fuzz/dictionary/obj.dict \
  -max_total_time=$((seconds / 2)) -rss_limit_mb=2048 -timeout=10 -max_len=8192 \
  -print_final_stats=1 2>&1 | tail -n 12
