#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The motion block's build-time parameters outside their ranges stop elaboration. The
# ranges are kBuildParams' (model/motion/build.hpp), generated into
# rtl/dda_motion_regs.vh as DDA_BUILD_<NAME>_MIN and _MAX; rtl/dda_motion.v instantiates
# a module that does not exist (dda_motion_<Parameter>_out_of_range) for a value outside
# them. For each parameter: each of the three tops elaborates on Icarus at the range's
# ends and fails one below and one above, naming that module; Verilator and Yosys fail
# on the block one above the range too, naming it.
#   usage: tests/check-build-ranges.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
for tool in "${IVERILOG:-iverilog}" "${VERILATOR:-verilator}" "${YOSYS:-yosys}"; do
  command -v "$tool" >/dev/null || { echo "check-build-ranges: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
mapfile -t srcs < <(scripts/rtl-files.sh rtl/dda_motion.f)
# (the three tops' sources, each once: the bridges' lists include the block's)
mapfile -t all < <( (scripts/rtl-files.sh rtl/dda_motion_axil.f; scripts/rtl-files.sh rtl/dda_motion_spi.f) | awk '!seen[$0]++')
# The parameters of dda_motion, in its order, and their ranges from the generated header.
mapfile -t params < <(sed -n '/^module dda_motion #(/,/^)/s/^ *parameter integer \([A-Za-z0-9]*\).*/\1/p' rtl/dda_motion.v)
[ "${#params[@]}" -gt 0 ] || { echo "check-build-ranges: no parameter found in rtl/dda_motion.v" >&2; exit 1; }
fail=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT
elab() {  # elab TOP PARAM VALUE: 0 when Icarus elaborates TOP with PARAM=VALUE
  "${IVERILOG:-iverilog}" -g2012 -Irtl -s "$1" -P"$1.$2=$3" -o /dev/null "${all[@]}" >"$log" 2>&1
}
checked=0
for p in "${params[@]}"; do
  name=$(tr '[:lower:]' '[:upper:]' <<<"$p")
  lo=$(sed -n "s/^\`define DDA_BUILD_${name}_MIN \([0-9-]*\)$/\1/p" rtl/dda_motion_regs.vh)
  hi=$(sed -n "s/^\`define DDA_BUILD_${name}_MAX \([0-9-]*\)$/\1/p" rtl/dda_motion_regs.vh)
  if [ -z "$lo" ] || [ -z "$hi" ]; then
    echo "check-build-ranges: rtl/dda_motion_regs.vh has no range for $p (DDA_BUILD_${name}_MIN/_MAX)" >&2
    fail=1
    continue
  fi
  grep -q "dda_motion_${p}_out_of_range u_bad" rtl/dda_motion.v ||
    { echo "check-build-ranges: rtl/dda_motion.v does not check $p's range" >&2; fail=1; }
  for top in dda_motion dda_motion_axil dda_motion_spi; do
    for v in "$lo" "$hi"; do
      elab "$top" "$p" "$v" || { echo "$top with $p=$v (in range): does not elaborate:" >&2; head -5 "$log" >&2; fail=1; }
    done
    for v in $((lo - 1)) $((hi + 1)); do
      if elab "$top" "$p" "$v"; then
        echo "$top with $p=$v (outside $lo..$hi): elaborates" >&2; fail=1
      elif ! grep -q "dda_motion_${p}_out_of_range" "$log"; then
        echo "$top with $p=$v: fails, but not naming dda_motion_${p}_out_of_range:" >&2; head -5 "$log" >&2; fail=1
      fi
      checked=$((checked + 1))
    done
  done
  v=$((hi + 1))
  if "${VERILATOR:-verilator}" --lint-only -Wall -Irtl --top-module dda_motion "-G$p=$v" "${srcs[@]}" rtl/lint.vlt \
    >"$log" 2>&1 || true; ! grep -q "dda_motion_${p}_out_of_range" "$log"; then
    echo "verilator: dda_motion with $p=$v does not fail naming dda_motion_${p}_out_of_range:" >&2
    head -5 "$log" >&2
    fail=1
  fi
  if "${YOSYS:-yosys}" -q -p "read_verilog -sv -Irtl ${srcs[*]}; hierarchy -check -top dda_motion -chparam $p $v" \
    >"$log" 2>&1; then
    echo "yosys: dda_motion with $p=$v elaborates" >&2; fail=1
  elif ! grep -q "dda_motion_${p}_out_of_range" "$log"; then
    echo "yosys: dda_motion with $p=$v fails, but not naming dda_motion_${p}_out_of_range:" >&2; head -5 "$log" >&2; fail=1
  fi
done
[ "$fail" = 0 ] || exit 1
echo "check-build-ranges: ${#params[@]} parameters (${params[*]}): the three tops elaborate at each range's ends" \
  "and $checked values outside fail on Icarus, one above each range on Verilator and Yosys too"
