#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What the pacer costs on the HX8K (docs/results.md, "The pacer's area"): Yosys
# synth_ice40 of rtl/dda_norm.v alone, of rtl/dda_pace.v with it, and of the pacer with
# the norm unit a black box (its own logic).
#   usage: scripts/pace-area.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cells() {  # cells TOP "YOSYS COMMANDS" FILE... -> "LUT4s flip-flops carry-cells"
  local top=$1 extra=$2
  shift 2
  yosys -q -p "read_verilog -sv -Irtl $*; $extra synth_ice40 -top $top; tee -o $work/stat.txt stat" >/dev/null
  awk '$1 == "SB_LUT4" {l += $2} $1 ~ /^SB_DFF/ {f += $2} $1 == "SB_CARRY" {c += $2}
       END {print l + 0, f + 0, c + 0}' "$work/stat.txt"
}
norm=$(cells dda_norm "" rtl/dda_norm.v)
pace=$(cells dda_pace "" rtl/dda_norm.v rtl/dda_pace.v)
own=$(cells dda_pace "blackbox dda_norm;" rtl/dda_norm.v rtl/dda_pace.v)
row() {  # row LABEL "LUT4s FFs carries"
  local l f c
  read -r l f c <<< "$2"
  printf '| %s | %d | %d | %d |\n' "$1" "$l" "$f" "$c"
}
echo "| Yosys synth_ice40 | LUT4s | flip-flops | carry cells |"
echo "|---|---|---|---|"
row "the norm unit (rtl/dda_norm.v)" "$norm"
row "the pacer with its norm unit (rtl/dda_pace.v)" "$pace"
row "the pacer, its norm unit a black box" "$own"
