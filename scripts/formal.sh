#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Formal proofs of the core with Debian's tools: Yosys reads the RTL (read_verilog
# -formal: the DDA_ASSERT assertions beside the logic become formal assertions),
# flattens the core and exposes its architectural registers (the register table, `dda
# gen-params --kind registers`) as outputs a_<name>; yosys-smtbmc with z3 proves.
#   usage: scripts/formal.sh [--impl small|fast] [--acc N] [--cnt N] [--depth K]
#                            [--solver z3|cvc4|cvc5] [--rtl DIR] [--expect-fail TEXT] JOB
#   JOB  props  k-induction of the assertions of one implementation (dda_props.sv): a
#               bounded check of K steps from reset, then the induction step of depth K
#        equiv  k-induction of a miter of the implementation against the reference core
#               (formal/ref/, the core before the small and fast implementations):
#               every port and every architectural register equal on every edge, and the reference's
#               assertions; the implementation's assertions are assumed there (props
#               proves them under the same environment: assume-guarantee)
#        cover  the cover traces of dda_props.sv, each reached within K steps
#        lemmas the carry-select adder, the three- and four-operand adders and the carry-free zero
#               test of the fast implementation (rtl/dda_add*.v, dda_sum_zero.v) equal
#               a + b, a + b + c + d and a + b == 0 (formal/dda_lemmas.sv). The jobs
#               above read the RTL with DDA_FORMAL_ABSTRACT, where those blocks are the
#               plain operations: a solver proves sums of sums, not carry-save layers
#               against them (that took minutes at 6 bits). Also the small
#               implementation's hand-placed iCE40 cells (rtl/dda_addsel.v with DDA_ICE40,
#               Yosys' SB_LUT4 and SB_CARRY models) equal its plain Verilog.
# --acc and --cnt choose the widths (default: those of hw_params.hpp); the header comes
# from `dda gen-params --kind verilog --acc-width N --cnt-width N`. Assumptions: the
# command preconditions and the integrand range the driver guarantees (formal/dda_env.vh).
# --rtl DIR proves a copy of the RTL (the sources of rtl/dda_core.f found in DIR, a
# mutant); --expect-fail TEXT then passes only if the proof fails on the assertion
# whose line in DIR holds TEXT (scripts/formal-mutants.sh).
# Work files (the SMT2 model, logs, counterexample and cover VCDs) go to
# $DDA_BUILD_DIR/formal/<job>-<impl>-<acc>-<cnt>/ (default build/). Exit 0 when proven
# (or, for cover, when every cover is reached). ctest -L formal runs it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
yosys=${YOSYS:-yosys} smtbmc=${YOSYS_SMTBMC:-yosys-smtbmc}
impl=small acc="" cnt="" depth="" rtl_dir=$root/rtl expect="" solver=z3
while [ $# -gt 1 ]; do
  case "$1" in
    --impl) impl=$2; shift 2 ;;
    --acc) acc=$2; shift 2 ;;
    --cnt) cnt=$2; shift 2 ;;
    --depth) depth=$2; shift 2 ;;
    --rtl) rtl_dir=$(cd "$2" && pwd); shift 2 ;;
    --expect-fail) expect=$2; shift 2 ;;
    --solver) solver=$2; shift 2 ;;
    *) break ;;
  esac
done
usage="usage: $0 [--impl small|fast] [--acc N] [--cnt N] [--depth K] [--solver z3|cvc4|cvc5] props|equiv|cover|lemmas"
[ $# -eq 1 ] || { echo "$usage" >&2; exit 2; }
job=$1
case "$job" in props|equiv|cover|lemmas) ;; *) echo "$usage" >&2; exit 2 ;; esac
case "$impl" in small|fast) ;; *) echo "formal: --impl must be small or fast, not '$impl'" >&2; exit 2 ;; esac
case "$solver" in z3|cvc4|cvc5) ;; *) echo "formal: --solver must be z3, cvc4 or cvc5, not '$solver'" >&2; exit 2 ;; esac
for tool in "$yosys" "$smtbmc" "$solver"; do
  command -v "$tool" >/dev/null || { echo "formal: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
dda=$build/bin/dda
[ -x "$dda" ] || { echo "formal: $dda not built (scripts/build.sh)" >&2; exit 1; }
widths=$("$dda" gen-params --kind json)
[ -n "$acc" ] || acc=$(echo "$widths" | sed -nE 's/.*"acc_width": ([0-9]+).*/\1/p')
[ -n "$cnt" ] || cnt=$(echo "$widths" | sed -nE 's/.*"cnt_width": ([0-9]+).*/\1/p')
if [ -z "$depth" ]; then
  case "$job" in cover) depth=12 ;; lemmas) depth=1 ;; *) depth=2 ;; esac
fi

[ "$job" = lemmas ] && impl=fast  # the blocks are the fast implementation's
work=$build/formal/$job-$impl-$acc-$cnt
[ "$rtl_dir" = "$root/rtl" ] || work=$build/formal/mutant-$(basename "$rtl_dir")-$job-$impl-$acc-$cnt
rm -rf "$work"
mkdir -p "$work/rtl" "$work/ref"
"$dda" gen-params --kind verilog --acc-width "$acc" --cnt-width "$cnt" --out "$work/rtl/dda_params.vh"
export DDA_RTL=$root/rtl
mapfile -t rtl_srcs < <("$root/scripts/rtl-files.sh" "$root/rtl/dda_core.f")
for f in "${rtl_srcs[@]}"; do cp "$rtl_dir/$(basename "$f")" "$work/rtl/"; done
cp "$root/rtl/dda_assert.vh" "$work/rtl/"
cp "$root"/formal/ref/*.v "$work/ref/"
cp "$root/formal/dda_env.vh" "$root/formal/dda_props.sv" "$root/formal/dda_lemmas.sv" "$work/"
# The register table at these widths (architectural registers and their widths).
mapfile -t regs < <("$dda" gen-params --kind registers --acc-width "$acc" --cnt-width "$cnt")

# Exposes the architectural registers of the flattened module $1 as outputs a_<name>.
expose() {
  echo "cd $1"
  for r in "${regs[@]}"; do
    local name=${r% *}
    echo "rename -output $name a_${name//./_}"
  done
  echo "cd .."
}

rtl_files=""
for f in "${rtl_srcs[@]}"; do rtl_files+=" $work/rtl/$(basename "$f")"; done
abstract=-DDDA_FORMAL_ABSTRACT
if [ "$job" = lemmas ]; then
  abstract=-DDDA_ICE40
  "$root/scripts/ice40-cells.sh" "$work/ice40_cells.v"
fi
{
  [ "$job" = lemmas ] && echo "read_verilog $work/ice40_cells.v"
  echo "read_verilog -formal $abstract -I$work/rtl$rtl_files"
  echo "chparam -set Impl \"$impl\" dda_core"
  if [ "$job" = lemmas ]; then
    echo "read_verilog -formal -sv -I$work/rtl $work/dda_lemmas.sv"
    echo "hierarchy -check -top dda_formal_lemmas"
    echo "proc; flatten; opt_clean; dffunmap; stat"
    echo "write_smt2 -wires $work/model.smt2"
  fi
} > "$work/model.ys"
[ "$job" = lemmas ] || {
  if [ "$job" = equiv ]; then
    echo "read_verilog -formal $abstract -I$work/rtl $work/ref/dda_counter_ref.v $work/ref/dda_integrator_ref.v $work/ref/dda_linear_ref.v $work/ref/dda_ctrl_ref.v $work/ref/dda_core_ref.v"
  fi
  echo "hierarchy -check"
  echo "proc"
  echo "flatten"
  expose dda_core
  if [ "$job" = equiv ]; then
    # Assume-guarantee: the implementation's own assertions (its invariants, proven by
    # the job props under the same environment) are assumptions here, so the induction
    # proves only that the two cores step alike from equal architectural states.
    echo "chformal -assert2assume dda_core"
    expose dda_core_ref
    echo "read_verilog -formal -sv -I$work/rtl -I$work $work/dda_equiv.sv"
    echo "hierarchy -check -top dda_formal_equiv"
  else
    echo "read_verilog -formal -sv -I$work/rtl -I$work $work/dda_props.sv"
    echo "hierarchy -check -top dda_formal_props"
  fi
  echo "proc"
  echo "flatten"
  echo "opt_clean"
  echo "dffunmap"
  echo "stat"
  echo "write_smt2 -wires $work/model.smt2"
} >> "$work/model.ys"

if [ "$job" = equiv ]; then
  # The miter: both cores on the same inputs; every port and architectural register equal.
  {
    echo "// Generated by scripts/formal.sh from the register table: do not edit."
    echo "\`include \"dda_params.vh\""
    echo "module dda_formal_equiv (input wire clk_i, input wire rst_ni, input wire ce_i,"
    echo "  input wire cmd_valid_i, input wire [\`DDA_CMD_WIDTH-1:0] cmd_i);"
    ports="cmd_ready_o step_x_o step_y_o dir_x_o dir_y_o step_z_o dir_z_o busy_o done_o err_o iter_o"
    for side in ref dut; do
      for p in $ports; do echo "  wire ${side}_$p;"; done
      for r in "${regs[@]}"; do
        name=${r% *} w=${r#* }
        echo "  wire [$w-1:0] ${side}_a_${name//./_};"
      done
    done
    for side in ref dut; do
      mod=dda_core; [ $side = ref ] && mod=dda_core_ref
      echo "  $mod u_$side ("
      echo "    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .cmd_valid_i(cmd_valid_i), .cmd_i(cmd_i),"
      for p in $ports; do echo "    .$p(${side}_$p),"; done
      n=${#regs[@]} i=0
      for r in "${regs[@]}"; do
        name=${r% *} i=$((i + 1))
        sep=","; [ $i -eq $n ] && sep=""
        echo "    .a_${name//./_}(${side}_a_${name//./_})$sep"
      done
      echo "  );"
    done
    echo "  wire cmd_ready = ref_cmd_ready_o;"
    echo "  wire [\`DDA_ACC_WIDTH-1:0] s_jv_x = ref_a_u_int_x_jv_q, s_jv_y = ref_a_u_int_y_jv_q, s_cap = ref_a_cap_q;"
    echo "  wire [\`DDA_CNT_WIDTH-1:0] s_cnt_x = ref_a_u_cnt_x_cnt_q, s_cnt_y = ref_a_u_cnt_y_cnt_q;"
    echo "  wire [\`DDA_ACC_WIDTH-1:0] s_inc_xx = ref_a_u_int_x_inc_on_x_q, s_inc_xy = ref_a_u_int_x_inc_on_y_q;"
    echo "  wire [\`DDA_ACC_WIDTH-1:0] s_inc_yx = ref_a_u_int_y_inc_on_x_q, s_inc_yy = ref_a_u_int_y_inc_on_y_q;"
    echo "  wire s_step_x = ref_step_x_o, s_step_y = ref_step_y_o, s_iter = ref_iter_o;"
    echo "\`include \"dda_env.vh\""
    echo "  always @(*) begin"
    echo "    if (!\$initstate) begin"
    for p in $ports; do echo "      assert (ref_$p == dut_$p);"; done
    for r in "${regs[@]}"; do
      name=${r% *}
      echo "      assert (ref_a_${name//./_} == dut_a_${name//./_});"
    done
    echo "    end"
    echo "  end"
    echo "endmodule"
  } > "$work/dda_equiv.sv"
fi

"$yosys" -q -l "$work/yosys.log" -s "$work/model.ys" >/dev/null ||
  { echo "formal: yosys failed (log: $work/yosys.log):" >&2; tail -20 "$work/yosys.log" >&2; exit 1; }
asserts=$(awk '$1 == "$assert" {s += $2} END {print s + 0}' "$work/yosys.log")
covers=$(awk '$1 == "$cover" {s += $2} END {print s + 0}' "$work/yosys.log")
echo "formal $job: implementation $impl, AccWidth $acc, CntWidth $cnt, depth $depth ($asserts assertions, $covers covers)"

start=$(date +%s.%N)
# --unroll: yosys-smtbmc expands the model's define-fun chains itself; z3 4.8.12 (Debian
# bookworm) hung for minutes with gigabytes of memory parsing the transition relation of
# this core (shared subterms expanded without sharing) even at AccWidth 8.
run() {  # run LABEL ARGS...: yosys-smtbmc, its log kept; fails with the log's tail
  local label=$1; shift
  if [ -n "$expect" ]; then
    # A mutant: the proof must fail, on the assertion whose source line holds $expect.
    if "$smtbmc" -s "$solver" --unroll "$@" "$work/model.smt2" >"$work/$label.log" 2>&1; then
      echo "  $label: passed, but the mutant must fail on: $expect" >&2
      return 1
    fi
    local lines
    lines=$(grep -nF -- "$expect" "$work"/rtl/*.v | sed -E 's#^([^:]+):([0-9]+):.*#\1:\2#')
    [ -n "$lines" ] || { echo "  formal: no assertion holds '$expect'" >&2; return 1; }
    local l
    for l in $lines; do
      local f=${l##*/}
      if grep -qE "Assert failed.*${f%%:*}:([0-9]+\.[0-9]+-)?${f##*:}\." "$work/$label.log"; then
        echo "  $label: failed as it must, on ${l##*/} ($expect)"
        return 0
      fi
    done
    echo "  $label: failed, but not on the assertion '$expect' (log: $work/$label.log)" >&2
    grep "Assert failed" "$work/$label.log" | head -5 >&2
    return 1
  fi
  if "$smtbmc" -s "$solver" --unroll --presat "$@" "$work/model.smt2" >"$work/$label.log" 2>&1; then
    echo "  $label: PASS ($(grep -m1 -oE 'Status: [A-Z]+' "$work/$label.log" || echo done))"
  else
    echo "  $label: FAIL (log: $work/$label.log)" >&2
    grep -E "Assert failed|failed|Reached cover|Unreached|Status" "$work/$label.log" | head -20 >&2
    return 1
  fi
}
case "$job" in
  lemmas)
    run lemmas -t "$depth" --dump-vcd "$work/lemmas-counterexample.vcd" ;;
  props|equiv)
    run bmc -t "$depth" --dump-vcd "$work/bmc-counterexample.vcd"
    [ -n "$expect" ] && exit 0
    run induction -i -t "$depth" --dump-vcd "$work/induction-counterexample.vcd" ;;
  cover)
    run cover -c -t "$depth" --dump-vcd "$work/cover%d.vcd"
    reached=$(grep -c "Reached cover statement" "$work/cover.log" || true)
    [ "$reached" -eq "$covers" ] || { echo "formal: $reached of $covers covers reached" >&2; exit 1; }
    echo "  $reached of $covers covers reached (traces: $work/cover*.vcd)" ;;
esac
awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "  solver time: %.1f s\n", e - s}'
