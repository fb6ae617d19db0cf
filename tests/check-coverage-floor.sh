#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The floor check of scripts/coverage.sh can fail: the DPI-C bench built with --coverage
# runs the paper's example with ce_i low a fifth of the cycles, and dda_counter is held to 100%
# line coverage (tests/data/coverage-floors-counter.json).
#   check-coverage-floor.sh BENCH RTL_DIR pass   the check passes on rtl/
#   check-coverage-floor.sh BENCH RTL_DIR fail   it fails, naming the planted branch's line
set -euo pipefail
bench=$1 rtl=$2 want=$3
src=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
DDA_COVERAGE_DIR=$tmp "$bench" "+dda_args=--a 10 --b 6 --bits 4 --preload zero" +stall=20 >/dev/null
status=0
python3 "$src/scripts/coverage.py" check "$tmp"/*.dat "$rtl" --floors "$src/tests/data/coverage-floors-counter.json" \
  >"$tmp/out.txt" || status=$?
cat "$tmp/out.txt"
if [ "$want" = pass ]; then
  [ $status -eq 0 ] || { echo "check-coverage-floor: the floor check failed on $rtl"; exit 1; }
  echo "check-coverage-floor: dda_counter holds its floor"
  exit 0
fi
line=$(grep -n "PLANTED" "$rtl/dda_counter.v" | head -1 | cut -d: -f1)
[ -n "$line" ] || { echo "check-coverage-floor: no planted branch in $rtl/dda_counter.v"; exit 1; }
if [ $status -ne 0 ] && grep -Eq "uncovered dda_counter.v:($line|$((line - 1))) " "$tmp/out.txt"; then
  echo "check-coverage-floor: the planted branch (dda_counter.v:$line) fails the floor check"
  exit 0
fi
echo "check-coverage-floor: the planted branch at dda_counter.v:$line was not reported"
exit 1
