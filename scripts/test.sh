#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, and runs every test through
# ctest. With --sanitize it does the same in a separate AddressSanitizer + UBSan build, less
# the long runs named in CMakePresets.json, whose code shorter tests also reach. With --quick
# it runs only the tests labelled unit (tests/CMakeLists.txt): under a minute after the build,
# for a contributor's edit-and-test loop; it is not the test command. WEFT_WARNINGS_AS_ERRORS=ON
# in the environment builds with -Werror (CI does).
usage="scripts/test.sh [--sanitize | --quick]"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail
cd "$(dirname "$0")/.."

preset=release
labels=()
case "${1:-}" in
  "") ;;
  --sanitize) preset=sanitize ;;
  --quick) labels=(-L '^unit$') ;;
  *)
    echo "error: $1: unknown option (usage: $usage)" >&2
    exit 2
    ;;
esac

scripts/setup.sh
options=()
if [ -n "${WEFT_WARNINGS_AS_ERRORS:-}" ]; then
  options=(-DWEFT_WARNINGS_AS_ERRORS="$WEFT_WARNINGS_AS_ERRORS")
fi
cmake --preset "$preset" "${options[@]}" >/dev/null
cmake --build --preset "$preset" -j 2
ctest --preset "$preset" "${labels[@]}"
