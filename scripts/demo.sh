#!/usr/bin/env bash
# The README's run command: installs what is missing, builds, and starts weft on its default
# scene. Arguments are passed to weft (a scene file, --set KEY=VALUE, ...).
usage="scripts/demo.sh [SCENE.toml] [weft options...]"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j 2 --target weft
exec build/release/src/app/weft "$@"
