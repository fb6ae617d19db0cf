#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The whole project built at other widths, and the tests that hold at any
# width run on it. Outside the default suite (a second build tree: about 5 minutes to
# build on 2 cores, 2 to 3 minutes to run).
#   usage: scripts/test-widths.sh [--acc N --cnt N] [--seed S]
# Default widths 43 and 13: semi-axes up to 2048 at every extra width the random arcs
# draw (5792 at the default n; `dda gen-params --kind json` in that tree says so), the
# rotated capacity 2^41. The tree is build-w<acc>-<cnt>/ beside build/ (or
# $DDA_WIDTHS_BUILD_DIR), configured with -DDDA_ACC_WIDTH=N -DDDA_CNT_WIDTH=N: the golden
# model, the planner and the SystemC model take the widths from hw_params.hpp, and the
# RTL is verilated with a header generated from it.
# What runs (the named subset):
#   test_golden '~[default-widths]'  every golden-model test except those tied to the
#                                    default widths (tagged [default-widths]): the
#                                    checked-in header and design tables, the default
#                                    widths' capacity, the lathe example (25000-step
#                                    axes: more steps than 13-bit counters hold), one
#                                    anchored example whose path depends on the
#                                    coefficients' rounding at 2^49, and sharp tips of
#                                    ellipses larger than these widths take
#   test_motion '~[default-widths]' the motion block in lockstep with its model (its
#                                    register map's checked-in files are the default
#                                    widths')
#   test_systemc, test_rtl, test_cosim, test_rtl_fast, test_cosim_fast
#                                    lockstep against the golden model on random arcs,
#                                    drawn within the widths (tb/random/dda_random.cpp);
#                                    one test case per process, as ctest runs them
#                                    (SystemC allows one simulation per process)
#   the paper's example through `dda trace` on the golden model, SystemC and the RTL:
#                                    the three traces are identical
#   the RTL and co-simulation regressions (scripts/regress.sh's programs) on 300 and 60
#   random arcs of every kind
# DDA_SEED (or --seed) reseeds the random tests, as in the default suite.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
acc=43 cnt=13
while [ $# -gt 0 ]; do
  case "$1" in
    --acc) acc=$2; shift 2 ;;
    --cnt) cnt=$2; shift 2 ;;
    --seed) export DDA_SEED=$2; shift 2 ;;
    *) echo "usage: $0 [--acc N --cnt N] [--seed S]" >&2; exit 2 ;;
  esac
done
build=${DDA_WIDTHS_BUILD_DIR:-$root/build-w$acc-$cnt}
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDDA_ACC_WIDTH="$acc" -DDDA_CNT_WIDTH="$cnt" >/dev/null
targets=(dda test_golden test_systemc test_rtl test_cosim test_rtl_fast test_cosim_fast test_motion rtl_regress cosim_regress)
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"
bin=$build/bin
echo "== widths: $("$bin/dda" gen-params --kind json | tr -d '\n ')"
fail=0
run() {
  echo "== $*"
  if ! "$@"; then echo "FAILED: $*" >&2; fail=1; fi
}
run "$bin/test_golden" '~[default-widths]'
run "$bin/test_motion" '~[default-widths]'
for t in test_systemc test_rtl test_cosim test_rtl_fast test_cosim_fast; do
  while IFS= read -r name; do
    # A test spec: commas, brackets and backslashes escaped (Catch2's spec syntax).
    [ -n "$name" ] && run "$bin/$t" --warn NoTests "$(printf '%s' "$name" | sed 's/[],[\\*]/\\&/g')"
  done < <("$bin/$t" --list-test-names-only)
done
work=$(mktemp -d -t dda-widths.XXXXXX)
trap 'rm -rf "$work"' EXIT
for e in golden systemc rtl; do
  "$bin/dda" trace --a 10 --b 6 --bits 4 --preload zero --engine "$e" > "$work/$e.txt"
done
echo "== dda trace --a 10 --b 6 --bits 4 --preload zero: golden, systemc, rtl"
if cmp -s "$work/golden.txt" "$work/systemc.txt" && cmp -s "$work/golden.txt" "$work/rtl.txt"; then
  echo "identical ($(wc -l < "$work/golden.txt") lines)"
else
  echo "FAILED: the engines' traces differ" >&2; diff "$work/golden.txt" "$work/rtl.txt" | head >&2; fail=1
fi
seed=${DDA_SEED:-1}
run "$bin/rtl_regress" --arcs 300 --seed "$seed"
run "$bin/cosim_regress" --arcs 60 --seed "$seed"
if [ "$fail" -ne 0 ]; then echo "test-widths: FAIL (AccWidth $acc, CntWidth $cnt)" >&2; exit 1; fi
echo "test-widths: PASS (AccWidth $acc, CntWidth $cnt)"
