#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Synthesize the RTL for iCE40 with Yosys and fail on any error, inferred latch or
# multiple/conflicting drivers; print the cell counts (stat).
#   usage: scripts/synth-check.sh [LOG_FILE]     (default: a temporary file)
# Registered in ctest as rtl.yosys_synth (tests/rtl_checks.cmake).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
yosys=${YOSYS:-yosys}
log=${1:-$(mktemp -t dda-synth.XXXXXX.log)}

cd "$root"
# check -assert: error on multiple conflicting drivers, undriven signals used, logic loops.
# select -assert-none: no latch cell of any kind survives (proc would have made one for
# an incomplete combinational assignment).
if ! "$yosys" -l "$log" -p "read_verilog -DDDA_ICE40 -Irtl $(scripts/rtl-files.sh rtl/dda_core.f | tr "\n" " "); \
    synth_ice40 -top dda_core; \
    check -assert; \
    select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr t:\$_DLATCH_* t:\$_DLATCHSR_*; \
    stat" >/dev/null; then
  echo "synth-check: FAIL: yosys exited with an error (log: $log)" >&2
  grep -Ei "warning|error" "$log" | grep -v "network is combinational" >&2 || true
  exit 1
fi
# The cell table of the last stat (the one after check).
stats=$(awk '/Printing statistics/ {buf = ""} {buf = buf $0 "\n"} END {printf "%s", buf}' "$log" |
        grep -E "Number of cells|^ +[\$A-Za-z_0-9]+ +[0-9]+$" || true)
echo "$stats"
fail=0
# proc reports "Latch inferred for signal ..." (and "No latch inferred ..." when fine).
if grep -i "latch inferred" "$log" | grep -qvi "no latch inferred"; then
  echo "synth-check: FAIL: a latch was inferred:" >&2
  grep -i "latch inferred" "$log" | grep -vi "no latch inferred" >&2
  fail=1
fi
if echo "$stats" | grep -qi "DLATCH"; then
  echo "synth-check: FAIL: latch cells in the netlist" >&2
  fail=1
fi
if grep -Eqi "multiple drivers|multiple conflicting drivers" "$log"; then
  echo "synth-check: FAIL: multiple drivers:" >&2
  grep -Ei "multiple drivers|multiple conflicting drivers" "$log" >&2
  fail=1
fi
if [ "$fail" -ne 0 ]; then exit 1; fi
echo "synth-check: PASS: synth_ice40 -top dda_core, no latch, no multiple drivers (log: $log)"
