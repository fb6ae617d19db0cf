#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Formal proofs of the motion block's buses and its step/dir stage with Debian's tools
# (Yosys, yosys-smtbmc, z3): a bounded check of K steps from reset, then the induction
# step of depth K.
#   usage: scripts/formal-bus.sh [--depth K] [--rtl DIR] [--expect-fail] JOB
#   JOB  wb    the block's Wishbone B4 slave (rtl/dda_motion.v, its queue at the smallest;
#              formal/bus/dda_wb_props.sv): one ack per request, none without one, the
#              stall rule, under any master, classic or pipelined
#        axil  the AXI4-Lite bridge (rtl/dda_axil.v; formal/bus/dda_axil_props.sv)
#        spi   the SPI bridge (rtl/dda_spi.v; formal/bus/dda_spi_props.sv): one access
#              per complete frame, none for any other
#        stepdir  the step/dir stage (rtl/dda_stepdir.v; formal/motion/dda_stepdir_props.sv):
#              its four timings at the pins and its one-step buffer, at the block's
#              timing width
# --rtl DIR proves a copy of the RTL (a mutant, scripts/formal-bus-mutants.sh); with
# --expect-fail the bounded check must then fail (a counterexample from reset).
# Work files (the SMT2 model, logs, counterexample VCDs) go to
# $DDA_BUILD_DIR/formal_bus/<job>/ (default build/). Exit 0 when proven. ctest -L formal.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
yosys=${YOSYS:-yosys} smtbmc=${YOSYS_SMTBMC:-yosys-smtbmc}
depth="" rtl_dir=$root/rtl expect=0
while [ $# -gt 1 ]; do
  case "$1" in
    --depth) depth=$2; shift 2 ;;
    --rtl) rtl_dir=$(cd "$2" && pwd); shift 2 ;;
    --expect-fail) expect=1; shift ;;
    *) break ;;
  esac
done
usage="usage: $0 [--depth K] [--rtl DIR] [--expect-fail] wb|axil|spi|stepdir"
[ $# -eq 1 ] || { echo "$usage" >&2; exit 2; }
job=$1
for tool in "$yosys" "$smtbmc" z3; do
  command -v "$tool" >/dev/null || { echo "formal-bus: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
# The sources, the module whose registers the properties see (renamed to outputs f_<name>)
# and the default depth of each job.
case "$job" in
  wb) list=$root/rtl/dda_motion.f top=dda_formal_wb module="" regs="" k=2 ;;
  axil) list=$root/rtl/dda_motion_axil.f top=dda_formal_axil module=dda_axil k=4
    regs="awaddr_q wdata_q wstrb_q araddr_q" ;;
  spi) list=$root/rtl/dda_motion_spi.f top=dda_formal_spi module=dda_spi k=6 regs="csn_q sck_q mosi_q cnt_q in_q" ;;
  stepdir) list=$root/rtl/dda_motion.f top=dda_formal_stepdir module=dda_stepdir k=2 regs="tf_q ts_q pend_q pdir_q"
    unroll=--unroll ;;  # z3 stalls at step 0 on this model without it (seconds with it)
  *) echo "$usage" >&2; exit 2 ;;
esac
depth=${depth:-$k}
unroll=${unroll:-}
work=$build/formal_bus/$job
[ "$rtl_dir" = "$root/rtl" ] || work=$build/formal_bus/$job-$(basename "$rtl_dir")
rm -rf "$work"
mkdir -p "$work/rtl"
# The sources of the list from rtl_dir (a mutant holds a copy of them), and the headers.
files=""
while IFS= read -r f; do
  b=$(basename "$f")
  [ "$job" != wb ] && [ "$b" != "$module.v" ] && continue
  cp "$rtl_dir/$b" "$work/rtl/"
  files+=" $work/rtl/$b"
done < <("$root/scripts/rtl-files.sh" "$list")
cp "$root"/rtl/*.vh "$work/rtl/"
cp "$rtl_dir"/*.vh "$work/rtl/" 2>/dev/null || true
{
  echo "read_verilog -formal -sv -I$work/rtl$files"
  echo "hierarchy -check"
  echo "proc"
  # The block's own assertions belong to the core's proofs: set aside here.
  [ "$job" = wb ] && echo "chformal -assert -remove"
  if [ -n "$module" ]; then
    echo "cd $module"
    for r in $regs; do echo "rename -output $r f_$r"; done
    echo "cd .."
  fi
  props=$root/formal/bus/dda_${top#dda_formal_}_props.sv
  [ "$job" = stepdir ] && props=$root/formal/motion/dda_stepdir_props.sv
  echo "read_verilog -formal -sv -I$work/rtl $props"
  echo "hierarchy -check -top $top"
  echo "proc; flatten; opt_clean; memory_nordff; dffunmap; stat"
  echo "write_smt2 -wires $work/model.smt2"
} > "$work/model.ys"
"$yosys" -q -l "$work/yosys.log" -s "$work/model.ys" >/dev/null || { tail -20 "$work/yosys.log" >&2; exit 1; }

run() {  # run LABEL ARGS...: yosys-smtbmc, its log kept
  local label=$1; shift
  "$smtbmc" -s z3 --presat $unroll "$@" "$work/model.smt2" >"$work/$label.log" 2>&1
}
if [ $expect -eq 1 ]; then
  if run bmc -t "$depth" --dump-vcd "$work/bmc-counterexample.vcd"; then
    echo "formal-bus $job: the bounded check of $depth steps passed on $rtl_dir, but it must fail" >&2
    exit 1
  fi
  grep -m1 "Assert failed" "$work/bmc.log" | sed 's/^.*Assert failed in /  failed as it must: /' || true
  exit 0
fi
run bmc -t "$depth" --dump-vcd "$work/bmc-counterexample.vcd" ||
  { tail -5 "$work/bmc.log" >&2; echo "formal-bus $job: the bounded check failed (log: $work/bmc.log)" >&2; exit 1; }
run induction -i -t "$depth" --dump-vcd "$work/induction-counterexample.vcd" ||
  { tail -5 "$work/induction.log" >&2; echo "formal-bus $job: the induction step failed (log: $work/induction.log)" >&2; exit 1; }
echo "formal-bus $job: proven (k-induction, depth $depth)"
