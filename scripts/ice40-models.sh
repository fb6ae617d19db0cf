#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Writes Yosys' simulation models of the iCE40 cells a netlist instantiates (and any cell
# named after it) to OUT, from the installed Yosys' ice40/cells_sim.v, for Icarus: the
# whole file has parts Icarus rejects, so OUT has its header's macros without the ports'
# default values (Icarus has none; every port is connected) and each module used. A cell
# given with --except is left out (a bench's own model, such as the PLL's). Fails when
# cells_sim.v has no model of a cell. Used by scripts/netlist-sim.sh and
# scripts/board-sim.sh (scripts/ice40-cells.sh writes the two cells of the hand-placed
# core for Verilator and the formal flow).
#   usage: scripts/ice40-models.sh NETLIST OUT [--except CELL]... [CELL...]
set -euo pipefail
usage="usage: $0 NETLIST OUT [--except CELL]... [CELL...]"
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
netlist=$1 out=$2
shift 2
extra=() except=()
while [ $# -gt 0 ]; do
  case "$1" in
    --except) [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }; except+=("$2"); shift 2 ;;
    *) extra+=("$1"); shift ;;
  esac
done
[ -r "$netlist" ] || { echo "ice40-models: cannot read $netlist" >&2; exit 2; }
bin=$(command -v "${YOSYS:-yosys}") || { echo "ice40-models: yosys not found (scripts/setup.sh installs it)" >&2; exit 1; }
cells_sim=$(cd "$(dirname "$(readlink -f "$bin")")/../share/yosys/ice40" 2>/dev/null && pwd)/cells_sim.v
[ -f "$cells_sim" ] || { echo "ice40-models: no $cells_sim" >&2; exit 1; }
used=$( (grep -oE '^ *SB_[A-Z0-9_]+' "$netlist" | tr -d ' '; printf '%s\n' "${extra[@]}") | sed '/^$/d' | sort -u)
for e in "${except[@]}"; do used=$(grep -vx "$e" <<<"$used" || true); done
{
  echo '`timescale 1ps / 1ps'
  echo '`define SB_DFF_INIT initial Q = 0;'
  echo '`define NO_ICE40_DEFAULT_ASSIGNMENTS'
  awk '/^`ifndef NO_ICE40_DEFAULT_ASSIGNMENTS/ {p = 1} p {print} p && /^`endif/ {exit}' "$cells_sim"
  for m in $used; do
    awk -v m="$m" '$0 ~ "^module " m " *\\(" {p = 1} p {print} p && /^endmodule/ {p = 0}' "$cells_sim"
  done
} >"$out"
for m in $used; do
  grep -q "^module $m *(" "$out" || { echo "ice40-models: no model of $m in $cells_sim" >&2; exit 1; }
done
