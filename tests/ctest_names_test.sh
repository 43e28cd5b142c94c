#!/usr/bin/env bash
# ctest's output pads every line to the longest test name, so one long name widens them all:
# value-parameterised tests once carried their whole "# GetParam() = ..." comment in their
# name (148 characters). Every name must stay short, and gtest's every test must still be a
# ctest test. Usage: ctest_names_test.sh BUILD_DIR GTEST_BINARY
set -uo pipefail
build=$1
gtest_binary=$2
longest_allowed=90

names=$(ctest --test-dir "$build" -N | sed -n 's/^ *Test *#[0-9]*: //p')
longest=$(printf '%s\n' "$names" | awk '{ if (length($0) > n) { n = length($0); s = $0 } } END { print n ": " s }')
echo "longest test name: $longest"
status=0
if [ "${longest%%:*}" -gt "$longest_allowed" ]; then
  echo "FAIL: a test name is longer than $longest_allowed characters"; status=1
fi
# gtest's own list: "Suite." lines then "  Test" lines; every one is a ctest test.
gtests=$("$gtest_binary" --gtest_list_tests | awk '/^[^ ]/ { suite = $1; next } { print suite $1 }')
missing=$(comm -23 <(printf '%s\n' "$gtests" | sort) <(printf '%s\n' "$names" | sort))
if [ -n "$missing" ]; then
  echo "FAIL: gtest tests with no ctest test:"; printf '%s\n' "$missing" | head; status=1
fi
echo "$(printf '%s\n' "$gtests" | wc -l) gtest tests, all in ctest"
exit $status
