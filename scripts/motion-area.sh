#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Where the motion block's own logic goes (docs/results.md, "The motion block on the
# HX8K"): Yosys synth_ice40 of rtl/dda_motion.v with the core a black box, as
# scripts/synth counts it, then of edited copies, each without one feature, so the
# difference is what that feature costs. The copies are made by exact text
# substitutions; a substitution that no longer matches the RTL stops the script.
#   usage: scripts/motion-area.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Every source of the block but rtl/dda_motion.v itself (the copies replace it).
other_srcs=$(scripts/rtl-files.sh rtl/dda_motion.f | grep -v '/dda_motion\.v$' | tr "\n" " ")

luts() {  # luts FILE [DEPTH_LOG2] -> "LUT4s flip-flops carry-cells"
  local chp=""
  [ -n "${2:-}" ] && chp="chparam -set DepthLog2 $2 dda_motion;"
  yosys -q -p "read_verilog -sv -DDDA_ICE40 -Irtl $other_srcs $1; blackbox dda_core; $chp \
    synth_ice40 -top dda_motion; tee -o $work/stat.txt stat" >/dev/null
  awk '$1 == "SB_LUT4" {l += $2} $1 ~ /^SB_DFF/ {f += $2} $1 == "SB_CARRY" {c += $2}
       END {print l + 0, f + 0, c + 0}' "$work/stat.txt"
}
variant() {  # variant NAME 'OLD' 'NEW' ['OLD' 'NEW' ...]: a copy of the RTL with edits
  local out="$work/$1.v"; shift
  cp rtl/dda_motion.v "$out"
  while [ $# -gt 0 ]; do
    grep -qF -- "$1" "$out" || { echo "motion-area: '$1' not in rtl/dda_motion.v" >&2; exit 1; }
    OLD="$1" NEW="$2" awk 'BEGIN {o = ENVIRON["OLD"]; n = ENVIRON["NEW"]}
      {i = index($0, o); if (i) $0 = substr($0, 1, i - 1) n substr($0, i + length(o)); print}' \
      "$out" > "$out.tmp" && mv "$out.tmp" "$out"
    shift 2
  done
  echo "$out"
}

luts_of() {  # luts_of STAT -> "N LUT4s, N flip-flops, N carry cells"
  awk '$1 == "SB_LUT4" {l += $2} $1 ~ /^SB_DFF/ {f += $2} $1 == "SB_CARRY" {c += $2}
       END {printf "%d LUT4s, %d flip-flops, %d carry cells", l, f, c}' "$1"
}
base=$(luts rtl/dda_motion.v)
read -r base_l base_f base_c <<< "$base"
row() {  # row LABEL "LUT4s FFs carries"
  local l f c
  read -r l f c <<< "$2"
  printf '| %s | %d | %d | %d | %+d |\n' "$1" "$l" "$f" "$c" $((l - base_l))
}
# Each figure in an assignment of its own, so that a failed edit or synthesis stops the script.
depth3=$(luts rtl/dda_motion.v 3)
f=$(variant nopreset '(wr_pos_x ? wdat : pos_x_q) + dx' 'pos_x_q + dx' \
  '(wr_pos_y ? wdat : pos_y_q) + dy' 'pos_y_q + dy' '(wr_pos_z ? wdat : pos_z_q) + dz' 'pos_z_q + dz')
nopreset=$(luts "$f")
f=$(variant count16 'reg [31:0] done_count_q' 'reg [15:0] done_count_q' 'reg [31:0] err_count_q' \
  'reg [15:0] err_count_q' "{31'd0, old_done} + {31'd0, new_done}" "{15'd0, old_done} + {15'd0, new_done}" \
  "{31'd0, core_err}" "{15'd0, core_err}")
count16=$(luts "$f")
f=$(variant noreadmux 'if (req && !wb_we_i) dat_q <= rd;' \
  'if (req && !wb_we_i) dat_q <= pos_x_q ^ pos_y_q ^ pos_z_q ^ done_count_q ^ err_count_q;')
noreadmux=$(luts "$f")
echo "| rtl/dda_motion.v, core a black box | LUT4s | flip-flops | carry cells | LUT4s vs the block |"
echo "|---|---|---|---|---|"
row "the block (queue 2^7 entries)" "$base"
row "queue 2^3 entries (DepthLog2 = 3)" "$depth3"
row "no position preset" "$nopreset"
row "done and err counters of 16 bits" "$count16"
row "read multiplexer replaced by the XOR of the five 32-bit registers" "$noreadmux"
# One step/dir stage by itself (three in the block).
yosys -q -p "read_verilog -sv -Irtl rtl/dda_stepdir.v; synth_ice40 -top dda_stepdir; tee -o $work/stat.txt stat" >/dev/null
echo
echo "one step/dir stage alone (rtl/dda_stepdir.v, 12-bit timings): $(awk '$1 == "SB_LUT4" {print $2}' "$work/stat.txt") LUT4s, $(awk '$1 ~ /^SB_DFF/ {s += $2} END {print s}' "$work/stat.txt") flip-flops, $(awk '$1 == "SB_CARRY" {print $2}' "$work/stat.txt") carry cells"
# The machine inputs by themselves (rtl/dda_motion_io.v: eleven inputs, the latches, the
# snapshot, the cycle counter), and one input's synchronizer and filter (the probe's
# counting clocks, a switch's counting ticks).
yosys -q -p "read_verilog -sv -Irtl rtl/dda_input.v rtl/dda_motion_io.v; synth_ice40 -top dda_motion_io; tee -o $work/stat.txt stat" >/dev/null
echo "the machine inputs alone (rtl/dda_motion_io.v): $(luts_of "$work/stat.txt")"
yosys -q -p "read_verilog -sv -Irtl rtl/dda_input.v; synth_ice40 -top dda_input; tee -o $work/stat.txt stat" >/dev/null
echo "one input alone (rtl/dda_input.v, a 16-bit filter, the probe's): $(luts_of "$work/stat.txt")"
yosys -q -p "read_verilog -sv -Irtl rtl/dda_input.v; chparam -set FW 4 dda_input; synth_ice40 -top dda_input; tee -o $work/stat.txt stat" >/dev/null
echo "one switch alone (rtl/dda_input.v, a 4-bit filter of ticks): $(luts_of "$work/stat.txt")"
# One position counter by itself: a 32-bit counter with a preset and a +-1 step.
cat > "$work/counter.v" <<'EOF'
module counter (input clk, input rst_ni, input wr, input [31:0] d, input step, input dir, output reg [31:0] q);
  wire [31:0] dx = step ? (dir ? 32'hFFFF_FFFF : 32'd1) : 32'd0;
  always @(posedge clk) if (!rst_ni) q <= 32'd0; else q <= (wr ? d : q) + dx;
endmodule
EOF
yosys -q -p "read_verilog $work/counter.v; synth_ice40 -top counter; tee -o $work/stat.txt stat" >/dev/null
echo "one position counter alone (32 bits, preset, +-1 step): $(awk '$1 == "SB_LUT4" {print $2}' "$work/stat.txt") LUT4s, $(awk '$1 == "SB_CARRY" {print $2}' "$work/stat.txt") carry cells"
