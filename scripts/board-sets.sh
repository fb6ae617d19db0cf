#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The board's vector sets (docs/board.md, "Checked by simulation"): `dda vectors --bus
# --bridge spi --build pacer=0` (the block behind its SPI slave in the board's build, at
# its 30 MHz clock), each short enough for a netlist on Icarus:
#   program  tests/data/board-program.ngc (a line, a quarter circle, a line; 0.02 mm steps)
#            at 200,000 steps/s, paced by the feed increments, with a drive's timings (a
#            2 us step pulse and space, 1 us direction set-up and hold: 60, 60, 30, 30
#            clocks)
#   hold     a quarter of an ellipse (a 60, b 40) at 300,000 steps/s, a feed hold at
#            cycle 14,000 and its end at 18,000, X's timings 20, 30, 10, 5 and its step
#            and direction inverted (POLARITY 3)
#   softstop the same quarter, a soft stop at cycle 16,000
#   estop    the E-stop scenario (--io-scenario estop: an E-stop in the middle of a piece,
#            the release, CTRL.clear and a move after it)
#   homing   the homing scenario (--io-scenario homing: each axis homed on a simulated
#            machine; without the pacer, its moves at feed increments)
# Prints each set's cycles.
#   usage: scripts/board-sets.sh [OUT_DIR]   (default $DDA_BUILD_DIR/board_sets)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
out=${1:-$build/board_sets}
[ -x "$build/bin/dda" ] || "$root/scripts/build.sh" >/dev/null
dda=$build/bin/dda
build_spec=$(sed -n 's|^// Board build: *||p' "$root/rtl/board/dda_hx8k_evn.v")
hz=$(sed -n 's/^ *parameter integer ClockHz *= *\([0-9_]*\).*/\1/p' "$root/rtl/board/dda_hx8k_evn.v" | tr -d _)
common=(--bus --bridge spi --build "$build_spec")
mkdir -p "$out"
make_set() {  # make_set NAME ARGS...
  local name=$1
  shift
  rm -rf "${out:?}/$name"
  "$dda" vectors "$@" "${common[@]}" --out-dir "$out/$name" >/dev/null
  echo "$name: $((16#$(cat "$out/$name/counts.hex"))) cycles ($out/$name)"
}
make_set program --program "$root/tests/data/board-program.ngc" --step 0.02 --feed-rate 200000 --clock "$hz" \
  --timing 60,60,30,30
make_set hold --a 60 --b 40 --feed-rate 300000 --clock "$hz" --hold-at 14000 --resume-at 18000 \
  --timing-x 20,30,10,5 --polarity 3
make_set softstop --a 60 --b 40 --feed-rate 300000 --clock "$hz" --soft-stop-at 16000
make_set estop --io-scenario estop
make_set homing --io-scenario homing
