#!/usr/bin/env bash
# The README's headless images are current: scripts/readme-images.sh redraws them into a
# scratch folder with this build's weft, and each must match the committed one but for at
# most 0.5 % of its pixels (a change in the simulation or the drawing beyond that means
# the README shows what weft no longer draws: rerun scripts/readme-images.sh).
# Usage: readme_images_test.sh WEFT PNG_DIFF SOURCE_DIR
set -uo pipefail
weft=$1
png_diff=$2
source_dir=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
source "$(dirname "$0")/cli_expect.sh"

WEFT=$weft "$source_dir/scripts/readme-images.sh" "$work" >"$work/log" 2>&1
check "readme-images.sh ran" test $? -eq 0
for image in "$work"/*.png; do
  name=$(basename "$image")
  committed=$source_dir/docs/images/$name
  check "$name is in docs/images" test -e "$committed"
  check "$name is linked from the README" grep -q "docs/images/$name" "$source_dir/README.md"
  differs=$("$png_diff" "$image" "$committed")
  echo "$name: $differs of the pixels differ"
  check "$name is current" awk -v f="$differs" 'BEGIN { exit !(f <= 0.005) }'
done
echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
