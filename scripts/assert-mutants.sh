#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The RTL's assertions fire: for each assertion a mutant (a fault injected into a copy of
# rtl/) on which the paper's vector set must end, under Icarus and under Verilator --assert, with the
# assertion that guards against that fault (not with a vector MISMATCH: each fault
# changes nothing before the edge where its assertion fires).
# --impl fast runs the same mutants on the fast implementation, and the mutants of its
# own assertions (its derived registers equal what they are derived from).
#   usage: scripts/assert-mutants.sh [--impl small|fast] VECTOR_SET_DIR
#   (ctest rtl.assertions_fire, rtl.fast.assertions_fire)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
impl=small
if [ "${1:-}" = --impl ]; then impl=$2; shift 2; fi
[ $# -eq 1 ] || { echo "usage: $0 [--impl small|fast] VECTOR_SET_DIR" >&2; exit 2; }
case "$impl" in small|fast) ;; *) echo "assert-mutants: --impl must be small or fast" >&2; exit 2 ;; esac
set_dir=$1

# name%file%anchor%replacement%assertion message
mutants=(
  "counter_underflow%dda_counter.v%cnt_d = cnt_q - dec;%cnt_d = cnt_q - dec - {{(CntWidth-1){1'b0}}, cnt_q == {CntWidth{1'b0}}};%ASSERTION dda_counter: a decrement at 0"
  "no_last_iteration%dda_ctrl.v%wire iterate  = run_ce & ~finished & ~stalled;%wire iterate  = run_ce & ~finished & ~stalled & ~(last_x_i & last_y_i);%ASSERTION dda_ctrl: in run with ce_i not exactly one of"
  "err_with_done%dda_ctrl.v%err_d   = stalled;%err_d   = stalled | finishing;%ASSERTION dda_ctrl: done and err together"
  "dir_without_step%dda_core.v%dir_x_d  = step_x_d ? cdir_x_q : dir_x_q;%dir_x_d  = cdir_x_q;%ASSERTION dda_core: dir_x_q changes without an X step"
  "cap_from_jr%dda_core.v%cmd_cap        = cmd_i[\`DDA_CMD_CAP_LSB%cmd_cap        = cmd_i[\`DDA_CMD_JR_X_LSB%ASSERTION dda_core: a loaded command is malformed"
)
# The fast implementation's derived registers, each made wrong in one way.
[ "$impl" = fast ] && mutants+=(
  "fast_e%dda_integrator.v%e_q      <= e_ld;%e_q      <= e_ld ^ {{(EW-1){1'b0}}, 1'b1};%ASSERTION dda_integrator(fast): e_q differs"
  "fast_incmc%dda_integrator.v%incmc_q  <= sx(inc_own_i) - {1'b0, cap_cmd_i};%incmc_q  <= sx(inc_own_i);%ASSERTION dda_integrator(fast): incmc_q differs"
  "fast_incsum%dda_integrator.v%incsum_q <= sx(inc_on_x_i) + sx(inc_on_y_i);%incsum_q <= sx(inc_on_x_i);%ASSERTION dda_integrator(fast): incsum_q differs"
  "fast_jvz%dda_integrator.v%jvz_q    <= jv_i == {AccWidth{1'b0}};%jvz_q    <= 1'b0;%ASSERTION dda_integrator(fast): jvz_q differs"
  "fast_add%dda_integrator.v%add_q <= add_d;%add_q <= 1'b1;%ASSERTION dda_integrator(fast): add_q differs"
  "fast_ovf%dda_integrator.v%ovf_q <= ovf_d;%ovf_q <= ovf_d | sel_it;%ASSERTION dda_integrator(fast): ovf_q differs"
  "fast_add_copy%dda_integrator.v%ce_a_q <= add_d;%ce_a_q <= 1'b0;%ASSERTION dda_integrator(fast): the copy of add_q"
  "fast_carry_copy%dda_integrator.v%cw_x_q <= ovf_x_d_i;%cw_x_q <= 1'b0;%ASSERTION dda_integrator(fast): a copy of the X carry"
  "fast_nz%dda_counter.v%nz_d  = ~one_q;%nz_d  = 1'b1;%ASSERTION dda_counter(fast): nz_q differs"
  "fast_one%dda_counter.v%one_d = cnt_q == Two;%one_d = 1'b0;%ASSERTION dda_counter(fast): one_q differs"
)
status=0
for m in "${mutants[@]}"; do
  IFS='%' read -r name file from to message <<< "$m"
  dir="$build/assert_mutants/$impl/$name"
  rm -rf "$dir"
  mkdir -p "$dir"
  # The sources of the file list, and the headers they include.
  "$root/scripts/rtl-files.sh" "$root/rtl/dda_core.f" | xargs cp -t "$dir/"
  cp "$root"/rtl/*.vh "$dir/"
  grep -qF "$from" "$dir/$file" || { echo "assert-mutants: anchor not found in rtl/$file: $from" >&2; exit 1; }
  FROM=$from TO=$to perl -0pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$dir/$file"
  echo "mutant $name ($file):"
  "$root/scripts/vector-bench.sh" --impl "$impl" --rtl "$dir" --expect "$message" "$set_dir" || status=1
done
exit $status
