#!/usr/bin/env bash
# Installs the Debian packages weft needs to build and test, and only those that are missing.
# Runs as root, or through sudo. Where installing is not possible it says what is missing
# and how to install it, and fails.
usage="scripts/setup.sh"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail

packages=(
  g++ make cmake pkg-config      # toolchain (CMake >= 3.25, C++20)
  libtomlplusplus-dev            # scene files
  libglm-dev                     # vector maths
  libgtest-dev                   # tests
  libsdl2-dev libimgui-dev       # the window and its parameter panel
  libstb-dev                     # PNG writing
  libbenchmark-dev               # micro-benchmarks
  xvfb xdotool                   # the end-to-end test drives the real window
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "weft: installing missing packages: ${missing[*]}"
how="apt-get update && apt-get install -y ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "weft: cannot install as a regular user without sudo. As root, run:" >&2
  echo "  $how" >&2
  exit 1
fi
# Refresh the package lists first: a fresh machine's may be stale or empty.
if ! "${sudo[@]}" apt-get update -qq ||
   ! DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"; then
  echo "weft: could not install: ${missing[*]}. Install them with:" >&2
  echo "  sudo $how" >&2
  exit 1
fi
