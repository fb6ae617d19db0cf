#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Writes Yosys' simulation models of the two iCE40 cells the small implementation places
# by hand (SB_LUT4, SB_CARRY; rtl/dda_addsel.v under DDA_ICE40) to OUT, taken from the
# installed Yosys' ice40/cells_sim.v (the models synth_ice40 maps to): the whole file
# takes Yosys 40 s to read and Icarus rejects parts of it, these two modules are plain.
#   usage: scripts/ice40-cells.sh OUT.v
# Used by scripts/formal.sh lemmas and scripts/vector-bench.sh --ice40.
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 OUT.v" >&2; exit 2; }
yosys=${YOSYS:-yosys}
bin=$(command -v "$yosys") || { echo "ice40-cells: $yosys not found (scripts/setup.sh installs it)" >&2; exit 1; }
cells=$(cd "$(dirname "$(readlink -f "$bin")")/../share/yosys/ice40" 2>/dev/null && pwd)/cells_sim.v
[ -f "$cells" ] || { echo "ice40-cells: no $cells" >&2; exit 1; }
{
  echo "// SB_LUT4 and SB_CARRY from $cells (scripts/ice40-cells.sh)"
  # Without the inputs' default values (Icarus has no port defaults; every port is connected).
  echo '`define ICE40_DEFAULT_ASSIGNMENT_0'
  echo '/* verilator lint_off DECLFILENAME */'
  awk '/^module (SB_LUT4|SB_CARRY) *\(/ {p = 1} p {print} p && /^endmodule/ {p = 0}' "$cells"
} > "$1.tmp"
n=$(grep -c '^module SB_' "$1.tmp" || true)
[ "$n" -eq 2 ] || { echo "ice40-cells: found $n of SB_LUT4, SB_CARRY in $cells" >&2; rm -f "$1.tmp"; exit 1; }
mv "$1.tmp" "$1"
