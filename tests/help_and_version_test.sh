#!/usr/bin/env bash
# Every program answers --help (usage on stdout, status 0) and --version (its name and the
# project version). weft-bench's studies are checked in weft_bench_cli_test.sh.
# Usage: help_and_version_test.sh VERSION PROGRAM...
set -uo pipefail
version=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
source "$(dirname "$0")/cli_expect.sh"

for program in "$@"; do
  name=$(basename "$program")
  expect 0 quiet -- --help
  check "$name --help prints its usage" grep -qi "usage" "$work/out"
  expect 0 quiet -- -h
  expect 0 quiet -- --version
  check "$name --version prints the project version" test "$(cat "$work/out")" = "$name $version"
done
echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
