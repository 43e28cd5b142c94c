#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, and runs every test through
# ctest. With --sanitize it does the same in a separate AddressSanitizer + UBSan build, less
# the long runs named in CMakePresets.json, whose code shorter tests also reach.
usage="scripts/test.sh [--sanitize]"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail
cd "$(dirname "$0")/.."

preset=release
if [ "${1:-}" = "--sanitize" ]; then
  preset=sanitize
fi

scripts/setup.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j 2
ctest --preset "$preset"
