#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# RTL code coverage of the default suite (docs/verification.md, "Code coverage"): a build
# tree of its own where every verilated model counts Verilator's line (branches
# included), toggle and user points (cmake -DDDA_COVERAGE=ON), the default suite run
# with DDA_COVERAGE_DIR (each harness writes its counts when it ends), the files merged
# by verilator_coverage, the sources annotated, the per-module table written and every
# module held to its floor (tests/coverage-floors.json; exclusions, each with its
# reason, in tests/coverage-exclusions.json). Exit status 1 when a test fails or a
# module is below its floor.
#
#   scripts/coverage.sh [BUILD_DIR [CTEST_ARGS...]]   (default build-coverage; about 45 min on 2 cores)
#
# Writes BUILD_DIR/coverage/: merged.dat, annotated/ (each rtl/ source with its counts),
# table.md (the table of docs/verification.md) and uncovered.txt (every point missed).
set -euo pipefail
cd "$(dirname "$0")/.."
bdir=${1:-build-coverage}
shift || true
jobs=$(nproc)

bash scripts/setup.sh
cmake -S . -B "$bdir" -DCMAKE_BUILD_TYPE=Release -DDDA_TESTS=ON -DDDA_COVERAGE=ON >/dev/null
cmake --build "$bdir" -j"$jobs"

out="$bdir/coverage"
rm -rf "$out"
mkdir -p "$out/data"
status=0
DDA_COVERAGE_DIR="$(cd "$out/data" && pwd)" ctest --test-dir "$bdir" -LE '^long$' -j"$jobs" --output-on-failure \
  "$@" >"$out/ctest.log" 2>&1 || status=1
tail -n 3 "$out/ctest.log"

shopt -s nullglob
files=("$out"/data/*.dat)
if [ ${#files[@]} -eq 0 ]; then
  echo "coverage: no coverage file was written (is $bdir a -DDDA_COVERAGE=ON build?)" >&2
  exit 1
fi
verilator_coverage --write "$out/merged.dat" "${files[@]}"
verilator_coverage --annotate "$out/annotated" --annotate-min 1 "$out/merged.dat" >/dev/null
args=("$out/merged.dat" rtl --exclusions tests/coverage-exclusions.json)
python3 scripts/coverage.py table "${args[@]}" >"$out/table.md"
python3 scripts/coverage.py uncovered "${args[@]}" >"$out/uncovered.txt"
cat "$out/table.md"
echo "coverage: ${#files[@]} files merged; annotated sources in $out/annotated, every missed point in $out/uncovered.txt"
python3 scripts/coverage.py check "${args[@]}" --floors tests/coverage-floors.json || status=1
exit $status
