#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The motion block's post-synthesis netlist against the golden vectors: Yosys
# synth_ice40 of the block (one of its builds, as scripts/synth synthesizes it), written
# out as Verilog (write_verilog -noattr), run by the bus bench tb/hdl/dda_bus_tb.v on
# Icarus with Yosys' simulation models of the iCE40 cells it uses (ice40/cells_sim.v), on
# bus vector sets (`dda vectors --bus`, docs/vectors.md): every output compared on every
# cycle, as scripts/vector-bench.sh --bus does for the RTL.
#   usage: scripts/netlist-sim.sh [--build SPEC] [--mutants N] [--seed S] SET...
# The sets must share one bus (their manifests' "bus": the block's top, as in
# vector-bench.sh) and one build (their manifests' "build": `dda vectors --bus --build`),
# which the script synthesizes; --build SPEC, when given, must be that build. --mutants
# N (0 or more) then shows that the comparison can fail: the netlist with the LUT that
# drives step_x_o inverted, with the LUT at the D of the register of read data bit 0
# (dat_q[0], Wishbone only) inverted, and N netlists each with one random LUT's init
# replaced by a random one that changes its function (scripts/netlist_mutants.py
# --random, seeds S .. S + N - 1, default 1): the first two, run on the first set, must
# fail; each random one runs on the sets in turn until one fails, and the script reports
# how many fail (a change in logic the sets never reach, or in input combinations they
# never make, passes; scripts/board-sim.sh --lut-coverage measures that for the board).
# Exit 1 when a set fails on the netlist or a directed mutant passes. A netlist runs a few hundred cycles a second on Icarus (the RTL: about 41,000),
# so the sets are the short ones. Work files in $DDA_BUILD_DIR/netlist_sim.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
spec="" mutants=-1 seed=1
while [ $# -gt 0 ]; do
  case "$1" in
    --build) spec=$2; shift 2 ;;
    --mutants) mutants=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    -*) echo "usage: $0 [--build SPEC] [--mutants N] [--seed S] SET..." >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || { echo "usage: $0 [--build SPEC] [--mutants N] [--seed S] SET..." >&2; exit 2; }
[[ "$mutants" =~ ^(-1|[0-9]+)$ ]] || { echo "netlist-sim: --mutants takes a count, not '$mutants'" >&2; exit 2; }
[[ "$seed" =~ ^[0-9]+$ ]] || { echo "netlist-sim: --seed takes a whole number, not '$seed'" >&2; exit 2; }
mkdir -p "$build" && build=$(cd "$build" && pwd)  # (absolute: the script changes folder)
for tool in yosys iverilog vvp python3; do
  command -v "$tool" >/dev/null || { echo "netlist-sim: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
sets=()
bus="" set_build=""
for s in "$@"; do
  [ -f "$s/manifest.json" ] || { echo "netlist-sim: $s is not a vector set (no manifest.json)" >&2; exit 2; }
  b=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("bus", "wishbone"))' "$s/manifest.json")
  [ -z "$bus" ] || [ "$b" = "$bus" ] || { echo "netlist-sim: $s is a $b set, the first a $bus one" >&2; exit 2; }
  bus=$b
  sb=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("build", ""))' "$s/manifest.json")
  [ ${#sets[@]} = 0 ] || [ "$sb" = "$set_build" ] || { echo "netlist-sim: $s is of the build '$sb', the first of '$set_build'" >&2; exit 2; }
  set_build=$sb
  sets+=("$(cd "$s" && pwd)")
done
# The sets' build (an older set names none: the default), and --build agreeing with it.
[ -x "$build/bin/dda" ] || "$root/scripts/build.sh" >/dev/null
if [ -n "$spec" ] && [ "$("$build/bin/dda" build "$spec")" != "$("$build/bin/dda" build "$set_build")" ]; then
  echo "netlist-sim: --build $spec is not the sets' build (${set_build:-the default})" >&2; exit 2
fi
spec=$set_build
case "$bus" in
  wishbone) top=dda_motion defs=() ;;
  axil|spi) top=dda_motion_$bus defs=("-DDDA_BVEC_$(echo "$bus" | tr a-z A-Z)") ;;
  *) echo "netlist-sim: unknown bus '$bus'" >&2; exit 2 ;;
esac
build_set=""
if [ -n "$spec" ]; then
  [ -x "$build/bin/dda" ] || "$root/scripts/build.sh" >/dev/null
  params=$("$build/bin/dda" build "$spec") || exit 2
  build_set=$(awk -v t="$top" '{printf "chparam -set %s %s %s; ", $1, $2, t}' <<<"$params")
fi
work=$build/netlist_sim
mkdir -p "$work"
cd "$root"
srcs=$(scripts/rtl-files.sh "rtl/$top.f" | tr "\n" " ")
echo "netlist-sim: synthesizing $top${spec:+ (build $spec)}"
yosys -q -l "$work/yosys.log" -p "read_verilog -sv -DDDA_ICE40 -Irtl $srcs; $build_set synth_ice40 -top $top; \
  write_verilog -noattr $work/netlist.v" >/dev/null
# Yosys' models of the cells the netlist uses (scripts/ice40-models.sh).
scripts/ice40-models.sh "$work/netlist.v" "$work/cells.v"

compile() {  # compile NETLIST OUT.vvp
  iverilog -g2012 "${defs[@]}" -Irtl -Itb/hdl -o "$2" tb/hdl/dda_bus_tb.v "$1" "$work/cells.v" 2>"$work/iverilog.log" ||
    { grep -v warning "$work/iverilog.log" >&2; exit 1; }
}
run() {  # run VVP SET: 0 when the bench passes
  vvp -n "$1" +vectors="$2" >"$work/run.log" 2>&1 && grep -q "dda_bus_tb: PASS" "$work/run.log"
}

compile "$work/netlist.v" "$work/netlist.vvp"
status=0
for s in "${sets[@]}"; do
  t0=$(date +%s.%N)
  if run "$work/netlist.vvp" "$s"; then
    echo "netlist: $(grep "dda_bus_tb: PASS" "$work/run.log") in $(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}') s"
  else
    echo "netlist: FAIL on $s:" >&2; tail -3 "$work/run.log" >&2; status=1
  fi
done
[ "$mutants" -ge 0 ] || exit $status

first=${sets[0]}
directed=(step_x_o)
[ "$bus" = wishbone ] && directed+=("dat_q[0]")
for net in "${directed[@]}"; do
  what=$(python3 scripts/netlist_mutants.py "$work/netlist.v" "$work/mutant.v" --drives "$net")
  compile "$work/mutant.v" "$work/mutant.vvp"
  if run "$work/mutant.vvp" "$first"; then
    echo "mutant (drives $net) $what: PASSED: the comparison did not see it" >&2; status=1
  else
    echo "mutant (drives $net) $what: fails ($(grep -m1 -E "MISMATCH|FAIL" "$work/run.log" | cut -c1-100))"
  fi
done
killed=0
for ((k = 0; k < mutants; k++)); do
  what=$(python3 scripts/netlist_mutants.py "$work/netlist.v" "$work/mutant.v" --random $((seed + k)))
  compile "$work/mutant.v" "$work/mutant.vvp"
  seen=""
  for s in "${sets[@]}"; do
    run "$work/mutant.vvp" "$s" || { seen=$(basename "$s"); break; }
  done
  if [ -n "$seen" ]; then
    killed=$((killed + 1))
    echo "random mutant $((seed + k)): $what: fails on $seen"
  else
    echo "random mutant $((seed + k)): $what: passes every set"
  fi
done
echo "random single-LUT mutants: $killed of $mutants fail on one of the sets"
exit $status
