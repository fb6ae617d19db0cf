#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The board top (rtl/board/dda_hx8k_evn.v) against the golden vectors, as RTL and as its
# two netlists, on Icarus: the bench tb/hdl/dda_board_tb.v compares every pin on every
# cycle (and, where the netlist keeps their names, the set's registers) with a vector set
# of the block behind its SPI bridge in the board's build (`dda vectors --bus --bridge
# spi --build pacer=0`; docs/board.md, "Checked by simulation").
#   usage: scripts/board-sim.sh [--netlist rtl|synth|routed|all|none] [--mutants N] [--seed S]
#                               [--lut-coverage] SET...
#   rtl     the RTL, with Yosys' model of SB_IO (registers compared too);
#   synth   the post-synthesis netlist: the JSON scripts/bitstream.sh placed and routed,
#           written out as Verilog (write_verilog -noattr), with Yosys' models of the cells
#           it uses (registers compared too);
#   routed  the routed bitstream's own netlist: icebox_vlog of the .asc scripts/bitstream.sh
#           wrote (pins only: it keeps no register names);
#   all     the three in turn (the default);
#   none    none of them (with --mutants: the mutants alone).
# The PLL is the bench's model (tb/hdl/dda_board_pll.v). --mutants N (0 or more) then
# shows that the comparison can fail: the routed netlist with the LUT that drives
# step_x_o inverted (with routed or all), and on the post-synthesis netlist: the netlist with the
# LUT that drives step_x_o inverted, with the LUT at the D of the SPI bridge's MISO
# register (the bit a read shifts out) inverted, N netlists each with one random LUT's
# init replaced by a random one, and N each with one random LUT's init flipped at one
# combination (scripts/netlist_mutants.py --kind init and bit, seeds S .. S + N - 1,
# default 1; only combinations the LUT's inputs can take: a change elsewhere changes
# nothing): the first two, run on the first set, must fail; each random one runs on the
# sets in turn, shortest first, until one fails (two at a time with GNU parallel), and
# the script reports how many of each kind fail. --lut-coverage runs the post-synthesis
# netlist on the sets with tb/hdl/sb_lut4_cov.v for Yosys' LUT model and prints how many
# of the LUTs' input combinations the sets reach (netlist_mutants.py --coverage-report);
# the random mutants' lines then say how many of the combinations they change the sets
# reach (a change the sets never reach cannot fail them). Runs scripts/bitstream.sh
# first when its outputs are missing or older than the sources. Exit 1 when a set fails or a directed mutant passes.
# Work files in $DDA_BUILD_DIR/board_sim.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
which=all mutants=-1 seed=1 coverage=0
usage="usage: $0 [--netlist rtl|synth|routed|all|none] [--mutants N] [--seed S] [--lut-coverage] SET..."
while [ $# -gt 0 ]; do
  case "$1" in
    --netlist|--mutants|--seed) [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; } ;;&
    --netlist) which=$2; shift 2 ;;
    --mutants) mutants=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --lut-coverage) coverage=1; shift ;;
    -*) echo "$usage" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
case "$which" in rtl|synth|routed|all|none) ;; *) echo "board-sim: --netlist is rtl, synth, routed, all or none, not '$which'" >&2; exit 2 ;; esac
[[ "$mutants" =~ ^(-1|[0-9]+)$ ]] || { echo "board-sim: --mutants takes a count, not '$mutants'" >&2; exit 2; }
[[ "$seed" =~ ^[0-9]+$ ]] || { echo "board-sim: --seed takes a whole number, not '$seed'" >&2; exit 2; }
[ "$which" != none ] || [ "$mutants" -ge 0 ] || [ "$coverage" = 1 ] ||
  { echo "board-sim: --netlist none runs only --mutants N or --lut-coverage" >&2; exit 2; }
mkdir -p "$build" && build=$(cd "$build" && pwd)
tools="iverilog vvp python3 yosys"
[ "$which" = rtl ] && [ "$mutants" -lt 0 ] || tools="$tools icebox_vlog"
for tool in $tools; do
  command -v "$tool" >/dev/null || { echo "board-sim: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
top=dda_hx8k_evn
# The board's build: the top's "Board build:" line, and its RTL parameters.
board_build=$(sed -n 's|^// Board build: *||p' "$root/rtl/board/$top.v")
[ -n "$board_build" ] || { echo "board-sim: no \"Board build:\" line in rtl/board/$top.v" >&2; exit 1; }
[ -x "$build/bin/dda" ] || "$root/scripts/build.sh" >/dev/null
board_params=$("$build/bin/dda" build "$board_build")
sets=()
for s in "$@"; do
  [ -f "$s/manifest.json" ] || { echo "board-sim: $s is not a vector set (no manifest.json)" >&2; exit 2; }
  case "$(cd "$s" && pwd)" in *[[:space:]]*) echo "board-sim: a set's path has a space: '$s'" >&2; exit 2 ;; esac
  read -r b spec < <(python3 -c 'import json,sys; m = json.load(open(sys.argv[1])); print(m.get("bus", "wishbone"), m.get("build", "default"))' "$s/manifest.json")
  [ "$b" = spi ] || { echo "board-sim: $s is a $b set: the board's block is behind its SPI bridge (--bridge spi)" >&2; exit 2; }
  [ "$spec" != default ] && [ "$("$build/bin/dda" build "$spec")" = "$board_params" ] ||
    { echo "board-sim: $s is of the build '$spec', not the board's ($board_build: --build $board_build)" >&2; exit 2; }
  sets+=("$(cd "$s" && pwd)")
done
work=$build/board_sim
mkdir -p "$work"
cd "$root"
# The netlists of the sources as they are: scripts/bitstream.sh again when its outputs are
# missing or older than a source, the pins or the script.
if { [ "$which" != rtl ] && [ "$which" != none ]; } || [ "$mutants" -ge 0 ] || [ "$coverage" = 1 ]; then
  stale=0
  [ -f "$build/board/$top.json" ] && [ -f "$build/board/$top.asc" ] || stale=1
  for f in $(scripts/rtl-files.sh rtl/board/$top.f) rtl/*.vh "rtl/board/$top.pcf" scripts/bitstream.sh; do
    [ "$stale" = 1 ] || [ ! "$f" -nt "$build/board/$top.asc" ] || stale=1
  done
  [ "$stale" = 0 ] || "$root/scripts/bitstream.sh"
fi

# Yosys' models of the cells a netlist uses but the PLL (the bench's model).
models() {  # models NETLIST OUT [extra cell ...]
  scripts/ice40-models.sh "$@" --except SB_PLL40_CORE
}
compile() {  # compile OUT.vvp DEFINES SOURCES...
  local out=$1 defs=$2
  shift 2
  # shellcheck disable=SC2086
  iverilog -g2012 $defs -Irtl -Itb/hdl -o "$out" tb/hdl/dda_board_tb.v tb/hdl/dda_board_pll.v "$@" \
    2>"$work/iverilog.log" || { grep -v warning "$work/iverilog.log" >&2; exit 1; }
}
run() {  # run VVP SET: 0 when the bench passes
  vvp -n "$1" +vectors="$2" >"$work/run.log" 2>&1 && grep -q "dda_board_tb: PASS" "$work/run.log"
}
status=0
run_sets() {  # run_sets NAME VVP
  local s t0
  for s in "${sets[@]}"; do
    t0=$(date +%s.%N)
    if run "$2" "$s"; then
      echo "$1: $(grep "dda_board_tb: PASS" "$work/run.log" | sed 's/^dda_board_tb: //') in $(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}') s"
    else
      echo "$1: FAIL on $s:" >&2; tail -3 "$work/run.log" >&2; status=1
    fi
  done
}

if [ "$which" = rtl ] || [ "$which" = all ]; then
  models /dev/null "$work/cells_rtl.v" SB_IO
  # shellcheck disable=SC2046
  compile "$work/rtl.vvp" "-DDDA_BOARD_REGS" $(scripts/rtl-files.sh rtl/board/$top.f) "$work/cells_rtl.v"
  run_sets rtl "$work/rtl.vvp"
fi
if [ "$which" = synth ] || [ "$which" = all ] || [ "$mutants" -ge 0 ] || [ "$coverage" = 1 ]; then
  # (synth.v keeps its time when the netlist is the same: a coverage file newer than it is
  # this netlist's)
  yosys -q -p "read_json $build/board/$top.json; write_verilog -noattr $work/synth.new.v" >/dev/null
  if cmp -s "$work/synth.new.v" "$work/synth.v"; then rm "$work/synth.new.v"; else mv "$work/synth.new.v" "$work/synth.v"; fi
  models "$work/synth.v" "$work/cells_synth.v"
fi
if [ "$which" = synth ] || [ "$which" = all ]; then
  compile "$work/synth.vvp" "-DDDA_BOARD_REGS -DDDA_BOARD_NETLIST" "$work/synth.v" "$work/cells_synth.v"
  run_sets "post-synthesis netlist" "$work/synth.vvp"
fi
if [ "$which" = routed ] || [ "$which" = all ]; then
  # (icebox_vlog reads set_io lines without nextpnr's -pullup option.)
  sed 's/-pullup yes //' "rtl/board/$top.pcf" >"$work/pins.pcf"
  icebox_vlog -s -c -d ct256 -n "$top" -p "$work/pins.pcf" "$build/board/$top.asc" >"$work/routed.v"
  models "$work/routed.v" "$work/cells_routed.v"
  compile "$work/routed.vvp" "" "$work/routed.v" "$work/cells_routed.v"
  run_sets "routed netlist" "$work/routed.vvp"
  if [ "$mutants" -ge 0 ]; then  # the routed netlist with the LUT that drives step_x_o inverted
    what=$(python3 scripts/netlist_mutants.py "$work/routed.v" "$work/routed_mutant.v" --routed-drives step_x_o)
    compile "$work/routed_mutant.vvp" "" "$work/routed_mutant.v" "$work/cells_routed.v"
    if run "$work/routed_mutant.vvp" "${sets[0]}"; then
      echo "routed mutant (drives step_x_o) $what: PASSED: the comparison did not see it" >&2; status=1
    else
      echo "routed mutant (drives step_x_o) $what: fails ($(grep -m1 -E "MISMATCH|FAIL" "$work/run.log" | cut -c1-100))"
    fi
  fi
fi
if [ "$coverage" = 1 ]; then
  models "$work/synth.v" "$work/cells_cov.v" --except SB_LUT4
  compile "$work/cov.vvp" "-DDDA_BOARD_REGS -DDDA_BOARD_NETLIST" "$work/synth.v" "$work/cells_cov.v" tb/hdl/sb_lut4_cov.v
  : >"$work/lut_coverage.new"
  for s in "${sets[@]}"; do
    t0=$(date +%s.%N)
    if run "$work/cov.vvp" "$s"; then
      echo "LUT coverage run: $(basename "$s"): passes in $(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}') s"
      grep "^LUTCOV " "$work/run.log" >>"$work/lut_coverage.new" || true  # (none: the report says so)
    else
      echo "LUT coverage run: FAIL on $s:" >&2; grep -v "^LUTCOV " "$work/run.log" | tail -3 >&2; status=1
    fi
  done
  mv "$work/lut_coverage.new" "$work/lut_coverage.txt"
  python3 scripts/netlist_mutants.py "$work/synth.v" --coverage-report "$work/lut_coverage.txt"
fi
[ "$mutants" -ge 0 ] || exit $status

first=${sets[0]}
for net in step_x_o "\\u_block.u_bridge.spi_miso_o "; do
  what=$(python3 scripts/netlist_mutants.py "$work/synth.v" "$work/mutant.v" --drives "$net")
  compile "$work/mutant.vvp" "-DDDA_BOARD_REGS -DDDA_BOARD_NETLIST" "$work/mutant.v" "$work/cells_synth.v"
  if run "$work/mutant.vvp" "$first"; then
    echo "mutant (drives $net) $what: PASSED: the comparison did not see it" >&2; status=1
  else
    echo "mutant (drives $net) $what: fails ($(grep -m1 -E "MISMATCH|FAIL" "$work/run.log" | cut -c1-100))"
  fi
done
# The random mutants, two at a time (GNU parallel, when installed), each on the sets
# from the shortest up until one fails.
by_size=$(for s in "${sets[@]}"; do echo "$((16#$(cat "$s/counts.hex"))) $s"; done | sort -n | cut -d' ' -f2- | tr '\n' ' ')
# The sets' LUT coverage, when a run of --lut-coverage on this netlist left it.
cov_opt=""
[ -f "$work/lut_coverage.txt" ] && [ "$work/lut_coverage.txt" -nt "$work/synth.v" ] && cov_opt="--coverage $work/lut_coverage.txt"
one_mutant() {  # one_mutant KIND K: prints its line
  local kind=$1 k=$2 m=$work/mutant_$1_$2 seen="" what s
  # shellcheck disable=SC2086
  what=$(python3 scripts/netlist_mutants.py "$work/synth.v" "$m.v" --random "$k" --kind "$kind" $cov_opt) ||
    { echo "random $kind mutant $k: not made"; return; }
  iverilog -g2012 -DDDA_BOARD_REGS -DDDA_BOARD_NETLIST -Irtl -Itb/hdl -o "$m.vvp" tb/hdl/dda_board_tb.v \
    tb/hdl/dda_board_pll.v "$m.v" "$work/cells_synth.v" 2>/dev/null || { echo "random $kind mutant $k: does not compile"; return; }
  for s in $by_size; do
    if ! vvp -n "$m.vvp" +vectors="$s" >"$m.log" 2>&1 || ! grep -q "dda_board_tb: PASS" "$m.log"; then
      seen=$(basename "$s")
      break
    fi
  done
  rm -f "$m.v" "$m.vvp" "$m.log"
  if [ -n "$seen" ]; then echo "random $kind mutant $k: $what: fails on $seen"; else echo "random $kind mutant $k: $what: passes every set"; fi
}
: >"$work/mutants.txt"
if [ "$mutants" -gt 0 ]; then
  if parallel --version 2>/dev/null | grep -q "GNU parallel"; then
    export -f one_mutant
    export work by_size cov_opt
    SHELL=$(command -v bash) parallel -j 2 -k one_mutant {1} {2} ::: init bit ::: $(seq "$seed" $((seed + mutants - 1))) \
      >"$work/mutants.txt"
  else
    for kind in init bit; do
      for ((k = seed; k < seed + mutants; k++)); do one_mutant "$kind" "$k"; done
    done >"$work/mutants.txt"
  fi
  cat "$work/mutants.txt"
fi
for kind in init bit; do
  killed=$(grep -c "^random $kind mutant .*: fails on " "$work/mutants.txt" || true)
  made=$(grep -c -E "^random $kind mutant .*: (fails on |passes every set)" "$work/mutants.txt" || true)
  case $kind in
    init) what="random single-LUT mutants (a LUT's init replaced)" ;;
    bit) what="random single-bit mutants (a LUT's init flipped at one combination)" ;;
  esac
  echo "$what: $killed of $made fail on one of the sets ($((mutants - made)) of $mutants not made or not compiled)"
  [ "$made" = "$mutants" ] || status=1
done
exit $status
