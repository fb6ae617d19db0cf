#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The part programs of examples/ at their planned speeds on the three engines, each with
# the machine and start of its "; Run:" line and the machine's options given (--step,
# --accel, --rapid, --default-feed, --min-speed: ctest speeds.examples_engines gives one
# slow machine that keeps every set near a million cycles), on a block clocked 5% over
# the slowest clock that follows the plan (program_cosim's choice).
# Per program:
#  - program_cosim (tb/cosim/program_cosim.cpp): the block's SystemC model, RTL and
#    reference model equal at every edge, the block at the program's end point, and the
#    speed monitor on the RTL's step and direction pins within the path's and each
#    axis' limits (speed and acceleration);
#  - `dda vectors --bus --speeds`: the set from the reference model, then
#    scripts/vector-bench.sh --bus: the RTL on Icarus and on Verilator, cycle for cycle.
# Sets are written to OUTDIR (each removed once its benches pass).
#   usage: tests/check-examples-speeds.sh DDA PROGRAM_COSIM EXAMPLES_DIR OUTDIR MACHINE_OPTIONS...
set -euo pipefail
[ $# -ge 5 ] || { echo "usage: $0 DDA PROGRAM_COSIM EXAMPLES_DIR OUTDIR MACHINE_OPTIONS..." >&2; exit 2; }
dda=$1 cosim=$2 dir=$3 out=$4
shift 4
speeds=("$@")
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
n=0
for prog in "$dir"/*.ngc; do
  name=$(basename "$prog" .ngc)
  listed=$("$here/../scripts/example-options.sh" "$prog")
  mapfile -t opts <<<"$listed"
  # program_cosim picks the block's clock: the slowest that follows the plan, 5% over,
  # in whole kHz; the bus set runs at the same.
  if ! ran=$("$cosim" "${opts[@]}" "${speeds[@]}" --seed 3 2>&1); then
    printf '%s\n' "$ran" >&2
    echo "examples at speeds: $name failed on the co-simulation" >&2
    exit 1
  fi
  line=$(sed -n '/^program_cosim: /p' <<<"$ran")
  echo "$line"
  clock=$(sed -n 's/^.* cycles at \([0-9]*\) Hz .*$/\1/p' <<<"$line")
  [ -n "$clock" ] || { printf '%s\n' "$ran" >&2; echo "examples at speeds: no clock for $name" >&2; exit 1; }
  rm -rf "${out:?}/$name"
  "$dda" vectors --bus "${opts[@]}" --speeds "${speeds[@]}" --clock "$clock" --seed 3 --max-size 1G --out-dir "$out/$name"
  "$here/../scripts/vector-bench.sh" --bus "$out/$name"
  echo "examples at speeds: $name: $((16#$(cat "$out/$name/counts.hex"))) cycles at $clock Hz: the bus set on Icarus and Verilator, the co-simulation with the reference model"
  rm -rf "${out:?}/$name"
  n=$((n + 1))
done
[ "$n" -ge 7 ] || { echo "examples at speeds: only $n programs in $dir (expected at least 7)" >&2; exit 1; }
echo "examples at speeds: $n programs at their planned speeds identical on the three engines, within the limits at the pins"
