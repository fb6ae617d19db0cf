#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fuzzing of the part-program reader (not in the default suite): builds the libFuzzer
# target tests/fuzz/fuzz_program.cpp with clang under AddressSanitizer and
# UndefinedBehaviorSanitizer, runs it for SECONDS (default 600) from the seed programs
# of tests/fuzz/corpus (G-code and macro programs), and prints libFuzzer's executions and coverage; then builds the
# reader's tests (tests/test_program.cpp) under the same sanitizers and runs them.
# Exits non-zero on a crash, a sanitizer report or a failed test.
#   usage: scripts/fuzz-program.sh [SECONDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-600}
out=${DDA_FUZZ_DIR:-$root/build-fuzz}
mkdir -p "$out/corpus"
cp "$root"/tests/fuzz/corpus/* "$out/corpus/"
srcs=("$root/model/src/program.cpp" "$root/model/src/program_grammar.cpp" "$root/model/src/program_macro.cpp"
  "$root/model/src/program_names.cpp"
  "$root/model/src/det_math.cpp" "$root/model/src/fixed_trig.cpp")
flags=(-std=c++17 -O1 -g -fno-omit-frame-pointer -ffp-contract=off -I"$root/model/include" -I"$root/model/src")
san=-fsanitize=address,undefined
clang++ "${flags[@]}" "$san",fuzzer -fno-sanitize-recover=undefined "${srcs[@]}" \
  "$root/tests/fuzz/fuzz_program.cpp" -lfmt -o "$out/fuzz_program"
echo "fuzz-program: running $seconds s from $(ls "$out/corpus" | wc -l) inputs"
"$out/fuzz_program" -max_total_time="$seconds" -print_final_stats=1 -max_len=4096 -artifact_prefix="$out/" \
  "$out/corpus" 2> "$out/fuzz.log" || { tail -40 "$out/fuzz.log"; echo "fuzz-program: FAILED" >&2; exit 1; }
grep -E "^#[0-9]+.*DONE|^Done [0-9]+ runs|stat::number_of_executed_units|stat::peak_rss_mb|cov:" "$out/fuzz.log" | tail -4
clang++ "${flags[@]}" "$san" -fno-sanitize-recover=undefined "${srcs[@]}" "$root/tests/test_program.cpp" \
  -lfmt -o "$out/test_program_san"
"$out/test_program_san" | grep -E "passed|failed"
echo "fuzz-program: PASS: no crash, no sanitizer report in $seconds s; the reader's tests pass under ASan and UBSan"
