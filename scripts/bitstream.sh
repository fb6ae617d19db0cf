#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bitstream of the board top for the Lattice iCE40-HX8K breakout board
# (rtl/board/dda_hx8k_evn.v, its pins rtl/board/dda_hx8k_evn.pcf; docs/board.md): Yosys
# synth_ice40, nextpnr-ice40 placed and routed for the board's clock (the top's ClockHz)
# on the placement seeds given until one meets it, icetime's timing check of the routed
# design at that clock, icepack. Prints the figures and the command that loads the
# bitstream into the board (iceprog -S: the FPGA's configuration RAM, the jumpers in the
# CRAM position, docs/board.md). Writes $DDA_BUILD_DIR/board/ (default build/board):
# dda_hx8k_evn.json (the post-synthesis netlist), .asc (the routed design), .bin, and the
# logs. Exit 1 when no seed meets the clock or icetime finds a path slower than it.
#   usage: scripts/bitstream.sh [--seeds "1 2 3"]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
seeds="1 2 3"
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds) seeds=$2; shift 2 ;;
    *) echo "usage: $0 [--seeds \"1 2 3\"]" >&2; exit 2 ;;
  esac
done
for s in $seeds; do
  [[ "$s" =~ ^[0-9]+$ ]] || { echo "bitstream: a seed is a whole number, not '$s'" >&2; exit 2; }
done
[ -n "${seeds// /}" ] || { echo "bitstream: --seeds needs at least one seed" >&2; exit 2; }
for tool in yosys nextpnr-ice40 icetime icepack; do
  command -v "$tool" >/dev/null || { echo "bitstream: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
top=dda_hx8k_evn
pcf=$root/rtl/board/$top.pcf
# The board's clock: the top's ClockHz, its one definition.
hz=$(sed -n 's/^ *parameter integer ClockHz *= *\([0-9_]*\).*/\1/p' "$root/rtl/board/$top.v" | tr -d _)
[ -n "$hz" ] || { echo "bitstream: no ClockHz in rtl/board/$top.v" >&2; exit 1; }
mhz=$(awk -v h="$hz" 'BEGIN {printf "%g", h / 1e6}')
out=$build/board
mkdir -p "$out"
cd "$root"
srcs=$(scripts/rtl-files.sh rtl/board/$top.f | tr "\n" " ")
echo "bitstream: synthesizing $top (Yosys synth_ice40)"
yosys -q -l "$out/yosys.log" -p "read_verilog -sv -DDDA_ICE40 -Irtl $srcs; synth_ice40 -top $top -json $out/$top.json; \
  check -assert; tee -q -o $out/stat.txt stat" >/dev/null
met=""
for s in $seeds; do
  log=$out/nextpnr-seed$s.log
  echo "bitstream: placing and routing for $mhz MHz, seed $s (nextpnr-ice40)"
  if ! nextpnr-ice40 --hx8k --package ct256 --json "$out/$top.json" --pcf "$pcf" --freq "$mhz" --seed "$s" \
    --asc "$out/$top.seed$s.asc" -l "$log" >/dev/null 2>&1; then
    grep -q "Max frequency for clock" "$log" || { echo "bitstream: nextpnr failed (seed $s):" >&2; tail -5 "$log" >&2; exit 1; }
  fi
  f=$(grep "Max frequency for clock" "$log" | tail -1 | sed -E 's/.*: ([0-9.]+) MHz.*/\1/')
  echo "seed $s: Fmax $f MHz (nextpnr)"
  if awk -v f="$f" -v m="$mhz" 'BEGIN {exit !(f >= m)}'; then met=$s; break; fi
done
[ -n "$met" ] || { echo "bitstream: no seed of \"$seeds\" meets $mhz MHz" >&2; exit 1; }
mv "$out/$top.seed$met.asc" "$out/$top.asc"
rm -f "$out"/$top.seed*.asc
cells=$(grep -E "ICESTORM_LC: +[0-9]+/" "$out/nextpnr-seed$met.log" | tail -1 | sed -E 's/.*ICESTORM_LC: +([0-9]+)\/ *([0-9]+).*/\1 of \2/')
# icetime's own timing check of the routed design at the board's clock (its topological
# analysis; -c fails when the longest path is slower than the clock).
icetime -d hx8k -P ct256 -p "$pcf" -c "$mhz" -t "$out/$top.asc" >"$out/icetime.log" 2>&1 || true
it=$(sed -nE 's/^Total path delay: [0-9.]+ ns \(([0-9.]+) MHz\).*/\1/p' "$out/icetime.log" | tail -1)
if [ -z "$it" ] || ! awk -v f="$it" -v m="$mhz" 'BEGIN {exit !(f >= m)}'; then
  tail -3 "$out/icetime.log" >&2
  echo "bitstream: icetime: the routed design misses $mhz MHz (${it:-no} MHz)" >&2
  exit 1
fi
icepack "$out/$top.asc" "$out/$top.bin"
echo "$top: $cells logic cells; seed $met: Fmax $(grep "Max frequency for clock" "$out/nextpnr-seed$met.log" | tail -1 | sed -E 's/.*: ([0-9.]+) MHz.*/\1/') MHz (nextpnr), $it MHz (icetime), board clock $mhz MHz: met"
echo "bitstream: $out/$top.bin"
echo "Load it into the board (its jumpers in the CRAM position: J6 1-2 and 3-4, J7 removed; docs/board.md):"
echo "  iceprog -S $out/$top.bin"
