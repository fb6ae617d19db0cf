#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every Catch2 test case is a ctest entry that runs it: for each Catch2 program in
# BIN_DIR, each name it lists must be (or end) the name of a ctest test. A test case
# missing from ctest never runs in the suite: a program whose catch_discover_tests was
# forgotten, or a name CMake's list handling cuts (a ';' in it did, and two tests
# with stale assertions went unseen).
#   usage: tests/check-discovery.sh BUILD_DIR
set -euo pipefail
build=$1
names=$(cd "$build" && ctest -N | sed -n 's/^ *Test *#[0-9]*: //p' | sed 's/ *$//')
missing=0 checked=0
for prog in "$build"/bin/test_*; do
  list=$("$prog" --list-test-names-only 2>/dev/null || true)  # (Catch2 v2 exits with the count)
  while IFS= read -r name; do
    [ -n "$name" ] || continue
    checked=$((checked + 1))
    if ! grep -qxF -- "$name" <<< "$names" && ! grep -qF -- ":$name" <<< "$names"; then
      echo "discovery: '$name' ($(basename "$prog")) is not a ctest test: it never runs" >&2
      missing=$((missing + 1))
    fi
  done <<< "$list"
done
[ "$checked" -gt 0 ] || { echo "discovery: no Catch2 test case found in $build/bin" >&2; exit 1; }
[ "$missing" -eq 0 ] || exit 1
echo "discovery: all $checked Catch2 test cases are ctest tests"
