#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every Catch2 test case is a ctest entry that runs it: for each Catch2 program in
# BIN_DIR, each name it lists must be (or end) the name of a ctest test. A test case
# missing from ctest never runs in the suite: a program whose catch_discover_tests was
# forgotten, or a name CMake's list handling cuts (a ';' in it did, and two tests
# with stale assertions went unseen).
# And every ctest entry carries a label (tests/CMakeLists.txt names them), so that a
# label's lane (`ctest -L quick`) is what it says.
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
unlabelled=$(cd "$build" && ctest --show-only=json-v1 | python3 -c '
import json, sys
for t in json.load(sys.stdin)["tests"]:
    if not any(p["name"] == "LABELS" and p["value"] for p in t.get("properties", [])):
        print(t["name"])')
if [ -n "$unlabelled" ]; then
  while IFS= read -r name; do echo "discovery: '$name' has no label" >&2; done <<< "$unlabelled"
  missing=$((missing + 1))
fi
[ "$missing" -eq 0 ] || exit 1
echo "discovery: all $checked Catch2 test cases are ctest tests, and every ctest entry has a label"
