#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs the self-checking bench tb/hdl/dda_vec_tb.v on a vector set written by
# `dda vectors`, under Icarus (iverilog -g2012 + vvp) and under Verilator (--binary).
#   usage: scripts/vector-bench.sh [--corrupt CYCLE FIELD] [--rtl RTLDIR --expect TEXT]
#                                  [--sim icarus|verilator|both] [--impl small|fast] [--ice40] [--bus] DIR
# --corrupt flips the lowest bit of FIELD in the expected word of CYCLE (in a copy of the
# set) and then passes only if every simulator fails with exactly that MISMATCH.
# --rtl runs a copy of the RTL (the sources of rtl/dda_core.f found in RTLDIR) and passes
# only if every simulator fails with a line containing TEXT (an assertion's message).
# --impl fast builds the core's fast implementation (-DDDA_IMPL_FAST; default small).
# --bus runs a bus-level set (`dda vectors --bus`) through tb/hdl/dda_bus_tb.v on the
# motion block (rtl/dda_motion.f) instead; a set of the block behind a bridge (its
# manifest's "bus": axil or spi) on the bridged top (rtl/dda_motion_axil.f,
# rtl/dda_motion_spi.f; the bench built with DDA_BVEC_AXIL or DDA_BVEC_SPI).
# --ice40 builds the RTL as scripts/synth synthesizes it (-DDDA_ICE40: the small
# implementation's hand-placed SB_LUT4 and SB_CARRY cells, with Yosys' models of them
# from scripts/ice40-cells.sh).
# The RTL's immediate assertions are on in both simulators (Verilator --assert).
# Builds go to $DDA_BUILD_DIR/vec_bench (default build/vec_bench). Registered in ctest
# (tests/rtl_checks.cmake, vectors.*).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
iverilog=${IVERILOG:-iverilog} vvp=${VVP:-vvp} verilator=${VERILATOR:-verilator}
corrupt_cycle="" corrupt_field="" sims="icarus verilator" rtl_dir=$root/rtl expect="" impl=small ice40=0 bus=0
while [ $# -gt 1 ]; do
  case "$1" in
    --corrupt) corrupt_cycle=$2 corrupt_field=$3; shift 3 ;;
    --rtl) rtl_dir=$(cd "$2" && pwd); shift 2 ;;
    --expect) expect=$2; shift 2 ;;
    --sim) sims=$2; [ "$sims" = both ] && sims="icarus verilator"; shift 2 ;;
    --impl) impl=$2; shift 2 ;;
    --ice40) ice40=1; shift ;;
    --bus) bus=1; shift ;;
    *) break ;;
  esac
done
[ $# -eq 1 ] || { echo "usage: $0 [--corrupt CYCLE FIELD] [--sim icarus|verilator|both] [--impl small|fast] [--ice40] DIR" >&2; exit 2; }
defs=()
case "$impl" in
  small) ;;
  fast) defs=(-DDDA_IMPL_FAST) ;;
  *) echo "vector-bench: --impl must be small or fast, not '$impl'" >&2; exit 2 ;;
esac
set_dir=$(cd "$1" && pwd)
out="$build/vec_bench"
[ "$rtl_dir" = "$root/rtl" ] || out="$build/vec_bench_$(basename "$rtl_dir")"
[ "$impl" = small ] || out="${out}_$impl"
[ "$ice40" = 0 ] || out="${out}_ice40"
bridge=wishbone
if [ "$bus" = 1 ]; then
  bridge=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("bus", "wishbone"))' \
    "$set_dir/manifest.json")
  # The bench runs the RTL at its default parameters: a set of another build is refused.
  set_build=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("build", ""))' "$set_dir/manifest.json")
  if [ -n "$set_build" ]; then
    [ -x "$build/bin/dda" ] || "$root/scripts/build.sh" >/dev/null
    [ "$("$build/bin/dda" build "$set_build")" = "$("$build/bin/dda" build "")" ] ||
      { echo "vector-bench: $set_dir is a set of the build $set_build: the bench runs the default build" \
          "(scripts/netlist-sim.sh and scripts/board-sim.sh take other builds)" >&2; exit 2; }
  fi
  case "$bridge" in
    wishbone) out="${out}_bus" ;;
    axil|spi) out="${out}_$bridge"; defs+=("-DDDA_BVEC_$(echo "$bridge" | tr a-z A-Z)") ;;
    *) echo "vector-bench: $set_dir/manifest.json: unknown bus '$bridge'" >&2; exit 2 ;;
  esac
fi
mkdir -p "$out"
# The RTL comes from its file list, rtl/dda_core.f, with DDA_RTL naming the folder
# (a mutated copy is the same list pointed at another folder).
export DDA_RTL=$rtl_dir
vl_extra=()  # a mutated copy may leave signals unused: its lint warnings do not stop the build
[ "$rtl_dir" = "$root/rtl" ] || vl_extra=(-Wno-fatal)
flist=$root/rtl/dda_core.f tb_top=dda_vec_tb
[ "$bus" = 0 ] || { flist=$root/rtl/dda_motion.f; tb_top=dda_bus_tb; }
[ "$bridge" = wishbone ] || flist=$root/rtl/dda_motion_$bridge.f
mapfile -t rtl_srcs < <("$root/scripts/rtl-files.sh" "$flist")
srcs=("$root/tb/hdl/$tb_top.v")
if [ "$ice40" = 1 ]; then
  defs+=(-DDDA_ICE40)
  [ -e "$out/ice40_cells.v" ] || "$root/scripts/ice40-cells.sh" "$out/ice40_cells.v"
  srcs+=("$out/ice40_cells.v")
fi
incs=(-I"$rtl_dir" -I"$root/rtl" -I"$root/tb/hdl")
newer() { local t=$1; shift; [ ! -e "$t" ] && return 0; for f in "$@"; do [ "$f" -nt "$t" ] && return 0; done; return 1; }
deps=("${srcs[@]}" "$flist")
for f in "${rtl_srcs[@]}"; do deps+=("$rtl_dir/${f#"$root/rtl/"}"); done
deps+=("$root/rtl/dda_params.vh" "$root/rtl/dda_assert.vh" "$root/tb/hdl/dda_vec_fields.vh"
       "$root/rtl/dda_motion_regs.vh" "$root/tb/hdl/dda_bus_vec_fields.vh" "$root/tb/hdl/dda_axil_vec_fields.vh"
       "$root/tb/hdl/dda_spi_vec_fields.vh")

if [ -n "$corrupt_cycle" ]; then
  work=$(mktemp -d -t dda-vec-corrupt.XXXXXX)
  trap 'rm -rf "$work"' EXIT
  cp "$set_dir"/* "$work/"
  # The field's bit range from the manifest (layout.cycle_exp), then flip its lowest bit.
  lsb=$(python3 -c 'import json,sys; m=json.load(open(sys.argv[1]))
for f in m["layout"]["cycle_exp"]:
    if f["name"] == sys.argv[2]: print(f["lsb"]); break
else: sys.exit("no field " + sys.argv[2])' "$set_dir/manifest.json" "$corrupt_field")
  python3 - "$work/cycle_exp.hex" "$corrupt_cycle" "$lsb" <<'PY'
import sys
path, cyc, lsb = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
lines = open(path).read().split("\n")
w = lines[cyc]
v = int(w, 16) ^ (1 << lsb)
lines[cyc] = format(v, "0%dx" % len(w))
open(path, "w").write("\n".join(lines))
PY
  set_dir=$work
fi

status=0
for sim in $sims; do
  case "$sim" in
    icarus)
      bin="$out/$tb_top.vvp"
      if newer "$bin" "${deps[@]}"; then "$iverilog" -g2012 "${defs[@]}" "${incs[@]}" -o "$bin" "${srcs[@]}" -c "$flist"; fi
      run=("$vvp" -n "$bin" +vectors="$set_dir") ;;
    verilator)
      bin="$out/obj/$tb_top"
      if newer "$bin" "${deps[@]}"; then
        "$verilator" --binary --assert -Wall "${defs[@]}" "${vl_extra[@]}" "${incs[@]}" --top-module "$tb_top" -Mdir "$out/obj" -o "$tb_top" \
          "${srcs[@]}" -f "$flist" >"$out/verilator-build.log" 2>&1 || { cat "$out/verilator-build.log" >&2; exit 1; }
      fi
      run=("$bin" +vectors="$set_dir") ;;
    *) echo "unknown simulator $sim" >&2; exit 2 ;;
  esac
  set +e
  log=$("${run[@]}" 2>&1)
  rc=$?
  set -e
  if [ -n "$expect" ]; then
    if [ $rc -ne 0 ] && echo "$log" | grep -qF "$expect"; then
      echo "$sim: failed as it must (exit $rc): $(echo "$log" | grep -F "$expect" | head -1)"
    else
      echo "$sim: did NOT fail with '$expect' (exit $rc):" >&2
      echo "$log" | tail -5 >&2; status=1
    fi
  elif [ -z "$corrupt_cycle" ]; then
    if [ $rc -eq 0 ] && echo "$log" | grep -q "$tb_top: PASS"; then
      echo "$sim: $(echo "$log" | grep "$tb_top: PASS")"
    else
      echo "$sim: FAIL (exit $rc):" >&2; echo "$log" | tail -5 >&2; status=1
    fi
  else
    want="MISMATCH cycle $corrupt_cycle field $corrupt_field:"
    if [ $rc -ne 0 ] && echo "$log" | grep -qF "$want"; then
      echo "$sim: failed as it must (exit $rc): $(echo "$log" | grep -F "$want")"
    else
      echo "$sim: did NOT report the corrupted value (exit $rc, wanted '$want'):" >&2
      echo "$log" | tail -5 >&2; status=1
    fi
  fi
done
exit $status
