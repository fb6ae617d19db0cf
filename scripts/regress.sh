#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Long regressions (not in the default test suite), each checked edge by edge against the
# reference model: random arcs back to back (quarter arcs, whole-ellipse arcs and arcs as
# programs give them, lines among them), some with random ce_i stalls, some reset on a
# random edge:
#   systemc  the SystemC model                       (default 2,000 cases)
#   rtl      the RTL under Verilator (--cc)          (default 100,000 cases)
#   cosim    SystemC model and RTL on one sc_clock   (default 2,000 cases)
#   rtl-fast, cosim-fast   the same on the core's fast implementation (dda_core.Impl)
#   motion   the motion block: SystemC model and RTL co-simulated on the bus, random
#            arcs queued with aborts, resets, partial commits and overflows
#            (default 1,000 arcs; one process, no shards)
#   long     the ctest entries labelled long, which scripts/test.sh leaves out: the fast
#            implementation's proofs, mutants and lathe vector set, the default-width
#            equivalence proof, the lathe bus set at 80% ce_i (about 14 min of test time)
# usage: scripts/regress.sh [systemc|rtl|cosim|rtl-fast|cosim-fast|motion|long|all] [cases] [seed] [shards]
# With shards > 1 the cases are cut into that many shards (--shard I/N), run with GNU
# parallel (one job per core; add e.g. --sshlogin to PARALLEL_OPTS to spread them over
# hosts that have the same build), and their JSON totals merged: every case draws from
# its own (seed, index) stream, so the merged totals equal one unsharded run's.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" >/dev/null
which=${1:-all}
seed=${3:-1}
shards=${4:-1}
run() {  # run PROGRAM CASES
  local prog=$build/bin/$1 cases=$2
  if [ "$shards" -le 1 ]; then
    "$prog" --arcs "$cases" --seed "$seed"
    return
  fi
  local work
  work=$(mktemp -d -t dda-regress.XXXXXX)
  # shellcheck disable=SC2086
  parallel --will-cite ${PARALLEL_OPTS:-} --halt now,fail=1 --line-buffer \
    "$prog" --arcs "$cases" --seed "$seed" --shard {}/"$shards" --json "$work/shard{}.json" \
    ::: $(seq 0 $((shards - 1)))
  "$prog" --merge "$work"/shard*.json
  rm -rf "$work"
}
case "$which" in
  systemc) run sc_regress "${2:-2000}" ;;
  rtl) run rtl_regress "${2:-100000}" ;;
  cosim) run cosim_regress "${2:-2000}" ;;
  rtl-fast) echo "the fast implementation (dda_core.Impl = \"fast\"):"; run rtl_regress_fast "${2:-100000}" ;;
  cosim-fast) echo "the fast implementation (dda_core.Impl = \"fast\"):"; run cosim_regress_fast "${2:-2000}" ;;
  motion)
    [ "$shards" -le 1 ] || { echo "regress: motion runs in one process (no shards)" >&2; exit 2; }
    "$build/bin/motion_regress" --arcs "${2:-1000}" --seed "$seed" ;;
  long) cd "$build" && ctest --output-on-failure -j "$(nproc)" -L '^long$' ;;
  all) run sc_regress "${2:-2000}"; run rtl_regress "${2:-100000}"; run cosim_regress "${2:-2000}" ;;
  *) echo "usage: $0 [systemc|rtl|cosim|rtl-fast|cosim-fast|motion|long|all] [cases] [seed] [shards]" >&2; exit 2 ;;
esac
