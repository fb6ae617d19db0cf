#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What the pacer costs on the HX8K (docs/results.md, "The pacer's area"): Yosys
# synth_ice40 of rtl/dda_norm.v alone, of rtl/dda_pace.v with it, and of a copy of the
# pacer without the override's multiplier (the override fixed at 100%), so the
# difference is what the multiplier costs; beside the motion block's own figure, to see
# whether the block with the pacer fits the device. A substitution that no longer
# matches the RTL stops the script.
#   usage: scripts/pace-area.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cells() {  # cells TOP FILE... -> "LUT4s flip-flops carry-cells"
  local top=$1
  shift
  yosys -q -p "read_verilog -sv -Irtl $*; synth_ice40 -top $top; tee -o $work/stat.txt stat" >/dev/null
  awk '$1 == "SB_LUT4" {l += $2} $1 ~ /^SB_DFF/ {f += $2} $1 == "SB_CARRY" {c += $2}
       END {print l + 0, f + 0, c + 0}' "$work/stat.txt"
}
old="wire [RF+OW:0] prod  = {{OW{1'b0}}, cruise_ovr} * (RF+OW+1)'(override_i);"
new="wire [RF+OW:0] prod  = {{OW{1'b0}}, cruise_ovr} << OF;"
grep -qF -- "$old" rtl/dda_pace.v || { echo "pace-area: the override's product is not in rtl/dda_pace.v" >&2; exit 1; }
OLD="$old" NEW="$new" awk 'BEGIN {o = ENVIRON["OLD"]; n = ENVIRON["NEW"]}
  {i = index($0, o); if (i) $0 = substr($0, 1, i - 1) n substr($0, i + length(o)); print}' \
  rtl/dda_pace.v > "$work/pace_noov.v"

norm=$(cells dda_norm rtl/dda_norm.v)
pace=$(cells dda_pace rtl/dda_norm.v rtl/dda_pace.v)
noov=$(cells dda_pace rtl/dda_norm.v "$work/pace_noov.v")
row() {  # row LABEL "LUT4s FFs carries"
  local l f c
  read -r l f c <<< "$2"
  printf '| %s | %d | %d | %d |\n' "$1" "$l" "$f" "$c"
}
echo "| Yosys synth_ice40 | LUT4s | flip-flops | carry cells |"
echo "|---|---|---|---|"
row "the norm unit (rtl/dda_norm.v)" "$norm"
row "the pacer with its norm unit (rtl/dda_pace.v)" "$pace"
row "the pacer without the override's multiplier" "$noov"
