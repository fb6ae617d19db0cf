#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Expands an RTL file list (rtl/dda_core.f, rtl/fpga/dda_fpga_top.f) into the paths of its
# Verilog sources, one per line, nested lists included: for Yosys, which reads no file
# lists. `+incdir+` lines are printed as `-I DIR` when --incdirs is given instead.
#   usage: scripts/rtl-files.sh [--incdirs] LIST.f
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=files
if [ "${1:-}" = --incdirs ]; then mode=incdirs; shift; fi
[ $# -eq 1 ] || { echo "usage: $0 [--incdirs] LIST.f" >&2; exit 2; }
rtl=$root/rtl
expand() {
  local line
  while IFS= read -r line || [ -n "$line" ]; do
    line=${line%%//*}
    line=$(echo "$line" | sed -e 's/^[[:space:]]*//' -e 's/[[:space:]]*$//' -e "s|\$(DDA_RTL)|$rtl|g")
    case "$line" in
      '') ;;
      -f\ *|-F\ *|-c\ *) expand "${line#* }" ;;
      +incdir+*) [ "$mode" = incdirs ] && echo "-I ${line#+incdir+}" ;;
      *) [ "$mode" = files ] && echo "$line" ;;
    esac
  done < "$1"
}
expand "$1"
