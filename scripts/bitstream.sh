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
# --mhz M builds for another clock: the top's ClockHz and PLL settings set to M MHz and
# `icepll -i 12 -o M`'s DIVR, DIVF, DIVQ and FILTER_RANGE (refused unless icepll reaches M
# exactly); the bitstream then runs the block at M MHz.
#   usage: scripts/bitstream.sh [--seeds "1 2 3"] [--mhz M]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
seeds="1 2 3" want_mhz=""
usage="usage: $0 [--seeds \"1 2 3\"] [--mhz M]"
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds|--mhz) [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; } ;;&
    --seeds) seeds=$2; shift 2 ;;
    --mhz) want_mhz=$2; shift 2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
for s in $seeds; do
  [[ "$s" =~ ^[0-9]+$ ]] || { echo "bitstream: a seed is a whole number, not '$s'" >&2; exit 2; }
done
[ -n "${seeds// /}" ] || { echo "bitstream: --seeds needs at least one seed" >&2; exit 2; }
for tool in yosys nextpnr-ice40 icetime icepack icepll; do
  command -v "$tool" >/dev/null || { echo "bitstream: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
top=dda_hx8k_evn
pcf=$root/rtl/board/$top.pcf
# The board's clock: the top's ClockHz, its one definition.
hz=$(sed -n 's/^ *parameter integer ClockHz *= *\([0-9_]*\).*/\1/p' "$root/rtl/board/$top.v" | tr -d _)
[ -n "$hz" ] || { echo "bitstream: no ClockHz in rtl/board/$top.v" >&2; exit 1; }
mhz=$(awk -v h="$hz" 'BEGIN {printf "%g", h / 1e6}')
clock_set=""
if [ -n "$want_mhz" ]; then
  [[ "$want_mhz" =~ ^[0-9]+(\.[0-9]+)?$ ]] || { echo "bitstream: --mhz takes a frequency in MHz, not '$want_mhz'" >&2; exit 2; }
  pll=$(icepll -i 12 -o "$want_mhz" 2>&1) || { echo "bitstream: icepll -i 12 -o $want_mhz failed" >&2; exit 2; }
  got=$(sed -nE 's/^F_PLLOUT: +([0-9.]+) MHz \(achieved\)/\1/p' <<<"$pll")
  awk -v a="$got" -v w="$want_mhz" 'BEGIN {exit !(a == w)}' ||
    { echo "bitstream: the PLL makes ${got:-no} MHz from 12 MHz, not $want_mhz exactly" >&2; exit 2; }
  field() { sed -nE "s/^$1: +([0-9]+) .*/\1/p" <<<"$pll"; }
  mhz=$(awk -v m="$want_mhz" 'BEGIN {printf "%g", m}')
  clock_set="chparam -set ClockHz $(awk -v m="$want_mhz" 'BEGIN {printf "%d", m * 1e6}') -set PllDivr $(field DIVR) \
    -set PllDivf $(field DIVF) -set PllDivq $(field DIVQ) -set PllFilter $(field FILTER_RANGE) $top;"
fi
out=$build/board
mkdir -p "$out"
cd "$root"
srcs=$(scripts/rtl-files.sh rtl/board/$top.f | tr "\n" " ")
# (icetime and icebox_vlog read set_io lines without nextpnr's -pullup option.)
sed 's/-pullup yes //' "$pcf" >"$out/pins-icetime.pcf"
echo "bitstream: synthesizing $top (Yosys synth_ice40)"
yosys -q -l "$out/yosys.log" -p "read_verilog -sv -DDDA_ICE40 -Irtl $srcs; $clock_set synth_ice40 -top $top \
  -json $out/$top.json; check -assert; tee -q -o $out/stat.txt stat" >/dev/null
met=""
for s in $seeds; do
  log=$out/nextpnr-seed$s.log
  echo "bitstream: placing and routing for $mhz MHz, seed $s (nextpnr-ice40)"
  rm -f "$out/$top.seed$s.asc"
  # (nextpnr exits 1 when the clock is missed; it writes the .asc only when it routed.)
  nextpnr-ice40 --hx8k --package ct256 --json "$out/$top.json" --pcf "$pcf" --freq "$mhz" --seed "$s" \
    --asc "$out/$top.seed$s.asc" -l "$log" >/dev/null 2>&1 || true
  if [ ! -f "$out/$top.seed$s.asc" ] || ! grep -q "Max frequency for clock" "$log"; then
    echo "seed $s: nextpnr did not route it:"; tail -3 "$log"
    continue
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
icetime -d hx8k -P ct256 -p "$out/pins-icetime.pcf" -c "$mhz" -t "$out/$top.asc" >"$out/icetime.log" 2>&1 || true
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
