#!/usr/bin/env bash
# Checks that every C++ file of weft's own is as clang-format leaves it, with the checked-in
# .clang-format (the Dear ImGui backends in src/app/imgui_backends are copied from upstream and
# keep upstream's style). Lists each file that differs and exits 1; installs clang-format if
# it is missing. CI runs it first (.ci/run).
usage="scripts/check-style.sh"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v clang-format >/dev/null; then
  echo "weft: installing missing packages: clang-format"
  sudo=(); [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends clang-format
fi

unformatted=()
while IFS= read -r file; do
  clang-format --dry-run --Werror "$file" >/dev/null 2>&1 || unformatted+=("$file")
done < <(git ls-files '*.cpp' '*.h' '*.inl' ':!src/app/imgui_backends/')
if [ ${#unformatted[@]} -gt 0 ]; then
  echo "error: not as clang-format leaves them (run clang-format -i on each):" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "clang-format: $(git ls-files '*.cpp' '*.h' '*.inl' ':!src/app/imgui_backends/' | wc -l) files as it leaves them"
