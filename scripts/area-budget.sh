#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Where the motion block's logic cells go on the iCE40 HX8K (docs/results.md, "Where the
# block's logic cells go"): Yosys synth_ice40 of rtl/dda_motion.v as scripts/synth
# makes it, packed by nextpnr-ice40 (not placed), then the same with a part replaced
# by a stub of the same ports, so that the difference is what the part costs packed:
#   - the pacer (rtl/dda_pace.v with its norm unit): the core iterates on every clock
#     it may (iterate_o = advance_i & running_i), the speed is 0;
#   - the norm unit alone (rtl/dda_norm.v): d is a register of x's operand's low bits,
#     so the pacer's logic around d stays;
#   - the machine inputs (rtl/dda_motion_io.v with its rtl/dda_input.v): no stop, no
#     interrupt cause, its registers read 0.
# and a copy of the RTL in which the running piece's constant fields are read where
# the queue holds them instead of copied at the take (the core's integrand corrections,
# capacities and Z integrand, the pacer's cruise, limit, exit and braking words): what
# those copies cost. That copy is not a working block (the queue fetches the next entry
# while a piece runs); a block that held the running entry would fetch after it.
# Each row: the packed cells of the device's and what they hold (a LUT4 with its
# flip-flop, a LUT4 alone, a flip-flop alone: its input is no LUT4 of its own, a carry
# alone, other: none of them, a constant); then the registers of the whole block with
# the most flip-flops alone.
#   usage: scripts/area-budget.sh [--alone N]   (N registers listed, default 20)
set -euo pipefail
shopt -s inherit_errexit  # (a failure inside $(...) stops the script too)
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
alone=20
while [ $# -gt 0 ]; do
  case "$1" in
    --alone) [[ ${2:-} =~ ^[0-9]+$ ]] || { echo "area-budget: --alone takes a number" >&2; exit 2; }
             alone=$2; shift 2 ;;
    *) echo "usage: $0 [--alone N]" >&2; exit 2 ;;
  esac
done
for tool in yosys nextpnr-ice40 python3; do
  command -v "$tool" >/dev/null || { echo "area-budget: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
work=$(mktemp -d -t dda-area.XXXXXX)
trap 'rm -rf "$work"' EXIT
srcs=$(scripts/rtl-files.sh rtl/dda_motion.f | tr "\n" " ")

# stub MODULE FILE BODY: the module's header (its parameters and ports, copied from
# FILE) with BODY instead of its logic.
stub() {
  local out="$work/$1_stub.v"
  MOD=$1 BODY=$3 python3 - "$2" > "$out" <<'PY'
import os, sys
src = open(sys.argv[1]).read()
start = src.index("module " + os.environ["MOD"])
end = src.index(");", src.index("output", start)) + 2
print('`include "dda_params.vh"')
print('`include "dda_motion_regs.vh"')
print(src[start:end])
print(os.environ["BODY"])
print("endmodule")
PY
  echo "$out"
}
# pack NAME SOURCES...: the packed design's cells (scripts/packed_cells.py's line).
pack() {
  local name=$1
  shift
  yosys -q -p "read_verilog -sv -DDDA_ICE40 -I${inc:-rtl} $*; synth_ice40 -top dda_motion -json $work/$name.json" >/dev/null
  nextpnr-ice40 --hx8k --package ct256 --json "$work/$name.json" --pack-only --write "$work/$name.packed.json" \
    -l "$work/$name.log" >/dev/null 2>&1 || { echo "area-budget: nextpnr failed to pack $name:" >&2; tail -5 "$work/$name.log" >&2; exit 1; }
  local device
  device=$(grep -E "ICESTORM_LC: +[0-9]+/ *[0-9]+" "$work/$name.log" | tail -1 | sed -E 's/.*\/ *([0-9]+).*/\1/')
  python3 scripts/packed_cells.py "$work/$name.packed.json" --alone "${alone_n:-0}" | sed "1s/\$/ device $device/"
}

pace_stub=$(stub dda_pace rtl/dda_pace.v "  assign iterate_o = advance_i & running_i;
  assign speed_o = '0;
  wire unused = &{1'b0, clk_i, rst_ni, take_i, cruise_i, limit_i, exit_i, length_i, brake_exit_i, next_queued_i,
                 accel_i, vmin_i, override_i, hold_i, stepped_i, v_x_i, v_y_i, v_z_i, cap_i, cap_z_i};")
norm_stub=$(stub dda_norm rtl/dda_norm.v "  reg [NF+1:0] d_q;
  always @(posedge clk_i) d_q <= start_i ? v_x_i[NF+1:0] : d_q;
  assign d_o = d_q;
  assign busy_o = 1'b0;
  wire unused = &{1'b0, rst_ni, v_x_i[AW-1:NF+2], v_y_i, v_z_i, cap_i, cap_z_i};")
no_pace=$(echo "$srcs" | tr " " "\n" | grep -v -e '/dda_pace\.v$' -e '/dda_norm\.v$' | tr "\n" " ")
io_stub=$(stub dda_motion_io rtl/dda_motion_io.v "  assign {hard_o, soft_o, err_o, probe_o, home_o, err_estop_o, err_limit_o, probe_armed_o, probed_o} = '0;
  always @(*) rd_o = 32'd0;
  wire unused = &{1'b0, clk_i, rst_ni, estop_ni, limit_i, home_i, probe_i, wr_i, adr_i, wdat_i, clear_i, snapshot_i,
                 probe_arm_i, pos_x_i, pos_y_i, pos_z_i, level_i, done_count_i, step_i, dir_i, pend_i, pdir_i};")
no_io=$(echo "$srcs" | tr " " "\n" | grep -v -e '/dda_motion_io\.v$' -e '/dda_input\.v$' | tr "\n" " ")
# The copy without the constant fields' copies: exact substitutions, each of which must
# match (a change of the RTL that breaks one stops the script).
mkdir -p "$work/held"
cp rtl/*.v rtl/*.vh "$work/held/"
python3 - "$work/held" <<'PY'
import sys
d = sys.argv[1]
edits = {
    "dda_integrator.v": [
        ("  reg [AccWidth-1:0] inc_on_x_q /* verilator public_flat_rd */;\n"
         "  reg [AccWidth-1:0] inc_on_y_q /* verilator public_flat_rd */;",
         "  wire [AccWidth-1:0] inc_on_x_q = inc_on_x_i;\n  wire [AccWidth-1:0] inc_on_y_q = inc_on_y_i;"),
        ("      inc_on_x_q <= {AccWidth{1'b0}};\n      inc_on_y_q <= {AccWidth{1'b0}};\n    end else if (load_i) begin\n"
         "      inc_on_x_q <= inc_on_x_i;\n      inc_on_y_q <= inc_on_y_i;\n    end", "    end")],
    "dda_linear.v": [
        ("  reg [AccWidth-1:0] jv_q  /* verilator public_flat_rd */;", "  wire [AccWidth-1:0] jv_q = jv_i;"),
        ("  reg [AccWidth-1:0] cap_q /* verilator public_flat_rd */;", "  wire [AccWidth-1:0] cap_q = cap_i;"),
        ("      jv_q  <= {AccWidth{1'b0}};\n      cap_q <= {AccWidth{1'b0}};\n    end else if (load_i) begin\n"
         "      jv_q  <= jv_i;\n      cap_q <= cap_i;\n    end", "    end")],
    "dda_core.v": [
        ("  reg [AccWidth-1:0] cap_q    /* verilator public_flat_rd */;", "  wire [AccWidth-1:0] cap_q = cmd_cap;"),
        ("    cap_d    = cap_q;\n", ""), ("      cap_d    = cmd_cap;\n", ""),
        ("      cap_q    <= {AccWidth{1'b0}};\n", ""), ("      cap_q    <= cap_d;\n", "")],
    "dda_pace.v": [
        ("  reg  [31:0]   cruise_q /* verilator public_flat_rd */;", "  wire [31:0] cruise_q = cruise_i;"),
        ("  reg  [31:0]   limit_q  /* verilator public_flat_rd */;", "  wire [31:0] limit_q = limit_i;"),
        ("  reg  [31:0]   exit_q   /* verilator public_flat_rd */;", "  wire [31:0] exit_q = exit_i;"),
        ("  reg  [31:0]   brake_q  /* verilator public_flat_rd */;", "  wire [31:0] brake_q = brake_exit_i;"),
        ("      cruise_q <= '0;\n      limit_q  <= '0;\n      exit_q   <= '0;\n      brake_q  <= '0;\n", ""),
        ("        cruise_q <= cruise_i;\n        limit_q  <= limit_i;\n        exit_q   <= exit_i;\n"
         "        brake_q  <= brake_exit_i;\n", "")],
}
for name, pairs in edits.items():
    path = d + "/" + name
    text = open(path).read()
    for old, new in pairs:
        if old not in text:
            sys.exit("area-budget: '" + old.splitlines()[0].strip() + "' not in rtl/" + name)
        text = text.replace(old, new)
    open(path, "w").write(text)
PY
held=$(echo "$srcs" | tr " " "\n" | sed "s|^$root/rtl/|$work/held/|" | tr "\n" " ")
for f in $held; do
  case "$f" in "$work/held/"*) ;; *) echo "area-budget: $f is not in the edited copy" >&2; exit 1 ;; esac
done
no_norm=$(echo "$srcs" | tr " " "\n" | grep -v '/dda_norm\.v$' | tr "\n" " ")

full=$(alone_n=$alone pack full $srcs)
nopace=$(pack nopace $no_pace "$pace_stub")
nonorm=$(pack nonorm $no_norm "$norm_stub")
noio=$(pack noio $no_io "$io_stub")
nocopy=$(inc=$work/held pack nocopy $held)
field() { echo "$1" | head -1 | awk -v k="$2" '{for (i = 1; i < NF; i += 2) if ($i == k) print $(i + 1)}'; }
row() {  # row LABEL LINE
  printf '| %s | %d (%.1f%%) | %d | %d | %d | %d | %d |\n' "$1" "$(field "$2" cells)" \
    "$(awk -v a="$(field "$2" cells)" -v b="$(field "$2" device)" 'BEGIN {print 100 * a / b}')" "$(field "$2" lut_ff)" \
    "$(field "$2" lut)" "$(field "$2" ff_alone)" "$(field "$2" carry_alone)" "$(field "$2" other)"
}
echo "rtl/dda_motion.v on the iCE40 HX8K (ct256), packed by nextpnr-ice40 (not placed), $(field "$full" device) logic cells"
echo
echo "| design | logic cells | LUT4 and flip-flop | LUT4 alone | flip-flop alone | carry alone | other |"
echo "|---|---|---|---|---|---|---|"
row "the block" "$full"
row "the block, the pacer a stub" "$nopace"
row "the block, the norm unit a stub" "$nonorm"
row "the block, the machine inputs a stub" "$noio"
row "the block, the running piece's constant fields not copied" "$nocopy"
echo
echo "the pacer with its norm unit: $(($(field "$full" cells) - $(field "$nopace" cells))) cells;" \
  "the norm unit: $(($(field "$full" cells) - $(field "$nonorm" cells))) cells (less its stub's 22-bit register);" \
  "the machine inputs: $(($(field "$full" cells) - $(field "$noio" cells))) cells;" \
  "the copies of the running piece's constant fields: $(($(field "$full" cells) - $(field "$nocopy" cells))) cells"
echo
echo "the block's registers with the most flip-flops alone:"
echo "$full" | tail -n +2
