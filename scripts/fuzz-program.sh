#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fuzzing of the part-program reader (not in the default suite): builds the libFuzzer
# target tests/fuzz/fuzz_program.cpp with clang under AddressSanitizer and
# UndefinedBehaviorSanitizer, runs it for SECONDS (default 600) from the seed programs
# of tests/fuzz/corpus and the project's LinuxCNC programs tests/programs/dda (G-code,
# HNC macro programs, LinuxCNC O-words, offsets, turning cycles, Fanuc programs), and
# prints libFuzzer's executions and coverage; then builds the reader's tests
# (tests/test_program*.cpp but the planner's) under the same sanitizers and runs them.
# Exits non-zero on a crash, a sanitizer report or a failed test.
#   usage: scripts/fuzz-program.sh [SECONDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-600}
out=${DDA_FUZZ_DIR:-$root/build-fuzz}
mkdir -p "$out/corpus"
cp "$root"/tests/fuzz/corpus/* "$root"/tests/programs/dda/*.ngc "$out/corpus/"
# The fuzz target and the sanitized tests are CMake targets (DDA_FUZZ: the reader's
# libraries only, built with clang).
CXX=clang++ cmake -S "$root" -B "$out/build" -DDDA_FUZZ=ON -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build "$out/build" --target fuzz_program test_program_san test_program_dialects_san \
  test_program_turning_san test_program_drill_san -j "$(nproc)" >/dev/null
echo "fuzz-program: running $seconds s from $(ls "$out/corpus" | wc -l) inputs"
"$out/build/bin/fuzz_program" -max_total_time="$seconds" -print_final_stats=1 -max_len=4096 -artifact_prefix="$out/" \
  "$out/corpus" 2> "$out/fuzz.log" || { tail -40 "$out/fuzz.log"; echo "fuzz-program: FAILED" >&2; exit 1; }
grep -E "^#[0-9]+.*DONE|^Done [0-9]+ runs|stat::number_of_executed_units|stat::peak_rss_mb|cov:" "$out/fuzz.log" | tail -4
"$out/build/bin/test_program_san" | grep -E "passed|failed"
"$out/build/bin/test_program_dialects_san" | grep -E "passed|failed"
"$out/build/bin/test_program_turning_san" | grep -E "passed|failed"
"$out/build/bin/test_program_drill_san" | grep -E "passed|failed"
echo "fuzz-program: PASS: no crash, no sanitizer report in $seconds s; the reader's tests pass under ASan and UBSan"
