#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Synthesis and place-and-route figures of the bus bridges on the iCE40 HX8K (ct256)
# (docs/results.md, "The bus bridges"): for each of AXI4-Lite (rtl/dda_axil.v) and SPI
# (rtl/dda_spi.v), Yosys synth_ice40 of the bridge alone (its LUT4s, flip-flops and
# carry cells: what it adds to the motion block), then nextpnr-ice40 with three
# placement seeds of the bridge in front of a block-RAM register file that answers as
# the block does (rtl/fpga/dda_bridge_top.v): the median Fmax and the placed logic cells.
#   usage: scripts/bridge-synth.sh [--seeds "1 2 3"]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seeds="1 2 3"
if [ "${1:-}" = --seeds ]; then seeds=$2; shift 2; fi
[ $# -eq 0 ] || { echo "usage: $0 [--seeds \"1 2 3\"]" >&2; exit 2; }
for tool in yosys nextpnr-ice40; do
  command -v "$tool" >/dev/null || { echo "bridge-synth: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
work=$(mktemp -d -t dda-bridge.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$root"
for bus in axil spi; do
  yosys -q -p "read_verilog -sv -Irtl rtl/dda_$bus.v; synth_ice40 -top dda_$bus; tee -o $work/$bus.stat stat" >/dev/null
  cells=$(awk '$1 == "SB_LUT4" {l += $2} $1 ~ /^SB_DFF/ {f += $2} $1 == "SB_CARRY" {c += $2}
    END {printf "%d LUT4s, %d flip-flops, %d carry cells", l, f, c}' "$work/$bus.stat")
  yosys -q -p "read_verilog -sv -Irtl rtl/dda_$bus.v rtl/fpga/dda_bridge_top.v; \
    chparam -set Bus \"$bus\" dda_bridge_top; synth_ice40 -top dda_bridge_top -json $work/$bus.json" >/dev/null
  fmaxes=()
  for s in $seeds; do
    log=$work/$bus-pnr$s.log
    if ! nextpnr-ice40 --hx8k --package ct256 --json "$work/$bus.json" --seed "$s" --freq 100 -l "$log" \
        >/dev/null 2>&1; then
      grep -q "Max frequency for clock" "$log" || { echo "bridge-synth: nextpnr failed ($bus, seed $s):" >&2; tail -5 "$log" >&2; exit 1; }
    fi
    fmaxes+=("$(grep "Max frequency for clock" "$log" | tail -1 | sed -E 's/.*: ([0-9.]+) MHz.*/\1/')")
  done
  fmax=$(printf '%s\n' "${fmaxes[@]}" | sort -n | awk '{a[NR] = $0} END {print a[int((NR + 1) / 2)]}')
  lcs=$(grep -m1 "ICESTORM_LC:" "$work/$bus-pnr${seeds%% *}.log" | sed -E 's/.*ICESTORM_LC: +([0-9]+)\/ *([0-9]+).*/\1/')
  echo "$bus: the bridge alone $cells; placed with its register file: $lcs logic cells, Fmax (median of $(echo $seeds | wc -w) seeds) $fmax MHz (seeds: ${fmaxes[*]})"
done
