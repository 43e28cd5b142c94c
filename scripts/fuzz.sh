#!/usr/bin/env bash
# Fuzzes the scene loader and --set parsing, then the session recordings that --replay reads
# (each replayed when small), then the OBJ reader and mesh builder (each small mesh stepped),
# with libFuzzer (clang, ASan + UBSan), seeded with assets/scenes, fuzz/sessions, fuzz/obj
# and the inputs earlier runs found (fuzz/regressions).
#   scripts/fuzz.sh            a short run: 60 s of scenes, 30 s each of sessions and OBJ
#                              files (CI runs scripts/fuzz.sh 40: 40 s and 20 s each)
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
# fuzz NAME SEEDS DICTIONARY SECONDS MAX_LEN: every earlier finding first (each must now load
# or be refused cleanly), then a run from a corpus seeded with SEEDS.
fuzz() {
  local fuzzer=build/fuzz/fuzz/weft_$1_fuzzer corpus=build/fuzz/$1-corpus
  "$fuzzer" -rss_limit_mb=2048 -timeout=10 fuzz/regressions/*
  mkdir -p "$corpus"
  cp -n $2 "$corpus"/
  "$fuzzer" "$corpus" -dict="$3" -max_total_time="$4" -rss_limit_mb=2048 -timeout=10 \
    -max_len="$5" -print_final_stats=1 2>&1 | tail -n 12
}
fuzz scene "assets/scenes/*.toml" fuzz/dictionary/scene.dict "$seconds" 4096
fuzz session "fuzz/sessions/*.toml" fuzz/dictionary/scene.dict $((seconds / 2)) 8192
fuzz obj "fuzz/obj/*.obj" fuzz/dictionary/obj.dict $((seconds / 2)) 8192
