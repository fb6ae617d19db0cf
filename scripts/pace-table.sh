#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The pacer's targets table of docs/results.md ("Motion a machine can follow"): the
# pacer's reference model (model/motion/pacer.hpp) on the golden datapath at 40 MHz,
# `dda feed --feed-rate F --accel A --clock 40e6 --summary` on the paper's example, the
# lathe arc, a 4:1 quarter ellipse, a full circle of radius 2000 and a 100 x 30 mm line
# (1 um per step), at feeds of 10 mm/min to 10 m/min (167 to 166,667 steps/s) and
# accelerations of 50 and 500 mm/s^2 (5e5 and 5e6 steps/s^2); and the block's rate at
# 40 MHz: 400,000 steps/s at 4e7 steps/s^2 on the full circle, a full 2000 x 500 ellipse
# and a 20000 x 6000 line. Runs the arcs in parallel
# (GNU parallel, one job per core).
#   usage: scripts/pace-table.sh [--write]   (--write puts it into docs/results.md)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dda=${DDA_BUILD_DIR:-$root/build}/bin/dda
[ -x "$dda" ] || { echo "pace-table: $dda not built (scripts/build.sh)" >&2; exit 1; }
arcs=(
  "the paper's example|--a 10 --b 6 --bits 4 --preload zero"
  "the lathe arc|--a 25000 --b 15000 --angle 330 --center -30000,5000 --from-theta 60 --to-theta 136 --dir ccw --preload zero"
  "a quarter ellipse 4000 x 1000|--a 4000 --b 1000 --preload half"
  "a full circle of radius 2000|--a 2000 --b 2000 --from-theta 0 --to-theta 0 --preload half"
  "a line 100000 x 30000|--line --from 0,0 --to 100000,30000 --preload half"
)
jobs=()
for arc in "${arcs[@]}"; do
  for accel in 5e5 5e6; do
    for feed in 167 1667 16667 166667; do
      jobs+=("${arc%%|*}|${arc#*|}|$feed|$accel")
    done
  done
done
fast=(
  "a full circle of radius 2000|--a 2000 --b 2000 --from-theta 0 --to-theta 0 --preload half"
  "a full ellipse 2000 x 500|--a 2000 --b 500 --from-theta 0 --to-theta 0 --preload half"
  "a line 20000 x 6000|--line --from 0,0 --to 20000,6000 --preload half"
)
for arc in "${fast[@]}"; do
  jobs+=("${arc%%|*}|${arc#*|}|400000|4e7")
done
run_one() {
  IFS='|' read -r label opts feed accel <<<"$1"
  # shellcheck disable=SC2086  # the arc's options are words
  "$DDA" feed $opts --feed-rate "$feed" --accel "$accel" --clock 40e6 --summary --label "$label"
}
export -f run_one
export DDA=$dda
table=$(
  echo "| arc | feed (steps/s) | acceleration (steps/s^2) | clock (Hz) | path (steps) | time (s) | ideal trapezoid (s) | time over ideal | worst feed error at cruise | commanded speed's change (of A) | pin monitor: acceleration (of A) | pin monitor: speed (of F) | last step (steps/s) | peak iteration rate (per s) |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${jobs[@]}" | parallel --keep-order -j "$(nproc)" run_one {}
)
if [ "${1:-}" = "--write" ]; then
  echo "$table" | "$root/scripts/results-table.sh" scripts/pace-table.sh "scripts/pace-table.sh --write"
else
  echo "$table"
fi
