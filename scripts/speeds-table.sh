#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The table of docs/results.md, "Programs at their planned speeds": every example
# program (with the machine and start of its "; Run:" line) and generated programs of
# lines, arcs and ellipses at random angles (10 blocks each, seeds 1 to 6, every axis'
# velocity 600 mm/min), on the slow machine of tests/slow-machine.options, through
# program_cosim (tb/cosim/program_cosim.cpp): the block's SystemC model and RTL
# co-simulated with the reference model, clocked 5% over the slowest clock that follows
# each plan; the block's time, the planned one, and the plan's profile on the DDA's path
# (the pacer's lengths, every rest reached and left at VMIN); the speed monitor on
# the RTL's pins (path and per axis, each figure the share of its limit), and the
# pacer's reference model at the same clock (its worst error at cruise against the
# planned speed, its worst piece end over the exit speed it was given). A run over a
# limit fails and stops the script. Two programs at a time (GNU parallel, one job per
# core).
#   usage: scripts/speeds-table.sh [--write]   (--write puts it into docs/results.md)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cosim=${DDA_BUILD_DIR:-$root/build}/bin/program_cosim
[ -x "$cosim" ] || { echo "speeds-table: $cosim not built (scripts/build.sh)" >&2; exit 1; }
read -ra machine < <(grep -v '^#' "$root/tests/slow-machine.options")
jobs=()
for prog in "$root"/examples/*.ngc; do
  jobs+=("$(tr '\n' ' ' < <("$root/scripts/example-options.sh" "$prog"))")
done
for seed in 1 2 3 4 5 6; do jobs+=("--random 1 --blocks 10 --vmax 600 --seed $seed"); done
run_one() {
  # shellcheck disable=SC2086  # the program's options are words
  "$COSIM" $1 $MACHINE --row
}
export -f run_one
export COSIM=$cosim MACHINE="${machine[*]}"
table=$(
  echo "| program | pieces | clock (Hz) | cycles | time (s) | planned (s) | DDA path (of programmed) | plan on the DDA path (s) | pins: path speed (of its limit) | path acceleration | each axis' speed | each axis' acceleration | pacer: cruise error | piece ends over the exit speed |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${jobs[@]}" | parallel --halt now,fail=1 --keep-order -j "$(nproc)" run_one {} |
    sed "s|$root/||"
)
if [ "${1:-}" = "--write" ]; then
  echo "$table" | "$root/scripts/results-table.sh" scripts/speeds-table.sh "scripts/speeds-table.sh --write"
else
  echo "$table"
fi
