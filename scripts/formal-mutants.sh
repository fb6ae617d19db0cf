#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every assertion written beside the logic fails on a mutated copy of the RTL under the
# formal proof (scripts/formal.sh props, bounded check from reset at AccWidth 8,
# CntWidth 4): for each assertion a fault that only it guards against, injected into a
# copy of rtl/; the proof must fail on that assertion. Both implementations take the
# shared mutants; the fast one also those of its derived registers.
#   usage: scripts/formal-mutants.sh [--impl small|fast]   (ctest formal.*.mutants)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
impl=small
if [ "${1:-}" = --impl ]; then impl=$2; shift 2; fi
case "$impl" in small|fast) ;; *) echo "formal-mutants: --impl must be small or fast" >&2; exit 2 ;; esac

# name%file%anchor%replacement%text on the line of the assertion that must fail
mutants=(
  "counter_underflow%dda_counter.v%cnt_d = cnt_q - dec;%cnt_d = cnt_q - dec - {{(CntWidth-1){1'b0}}, cnt_q == {CntWidth{1'b0}}};%a decrement at 0"
  "no_last_iteration%dda_ctrl.v%wire iterate  = run_ce & ~finished & ~stalled;%wire iterate  = run_ce & ~finished & ~stalled & ~(last_x_i & last_y_i);%not exactly one of finished"
  "err_with_done%dda_ctrl.v%err_d   = stalled;%err_d   = stalled | finishing;%done and err together"
  "ce_ignored%dda_ctrl.v%wire run_ce   = (state_q == StRun) & ce_i;%wire run_ce   = (state_q == StRun);%run with ce_i low changes state"
  "busy_late%dda_ctrl.v%assign busy_o = state_q == StRun;%assign busy_o = (state_q == StRun) | done_q;%busy_o differs from running"
  "dir_without_step%dda_core.v%dir_x_d  = step_x_d ? cdir_x_q : dir_x_q;%dir_x_d  = cdir_x_q;%dir_x_q changes without an X step"
  "step_without_iteration%dda_core.v%step_x_d = iterate & ovf_x;%step_x_d = ovf_x;%a step without an iteration"
  "cap_from_jr%dda_core.v%cmd_cap        = cmd_i[\`DDA_CMD_CAP_LSB%cmd_cap        = cmd_i[\`DDA_CMD_JR_X_LSB%a loaded command is malformed"
)
if [ "$impl" = small ]; then
  mutants+=("never_subtract%dda_integrator.v%if (add) jr_q <= ovf ? sum_minus_cap : sum[AccWidth-1:0];%if (add) jr_q <= sum[AccWidth-1:0];%the accumulator is not below the capacity")
else
  mutants+=(
    "never_subtract%dda_integrator.v%if (add_q) jr_q <= jr_it;%if (add_q) jr_q <= sum[AccWidth-1:0];%the accumulator is not below the capacity"
    "fast_e%dda_integrator.v%e_q      <= e_ld;%e_q      <= e_ld ^ {{(EW-1){1'b0}}, 1'b1};%e_q differs"
    "fast_incmc%dda_integrator.v%incmc_q  <= sx(inc_own_i) - {1'b0, cap_cmd_i};%incmc_q  <= sx(inc_own_i);%incmc_q differs"
    "fast_incsum%dda_integrator.v%incsum_q <= sx(inc_on_x_i) + sx(inc_on_y_i);%incsum_q <= sx(inc_on_x_i);%incsum_q differs"
    "fast_jvz%dda_integrator.v%jvz_q    <= jv_i == {AccWidth{1'b0}};%jvz_q    <= 1'b0;%jvz_q differs"
    "fast_add%dda_integrator.v%add_q <= add_d;%add_q <= 1'b1;%add_q differs"
    "fast_ovf%dda_integrator.v%ovf_q <= ovf_d;%ovf_q <= ovf_d | sel_it;%ovf_q differs"
    "fast_add_copy%dda_integrator.v%ce_a_q <= add_d;%ce_a_q <= 1'b0;%the copy of add_q"
    "fast_carry_copy%dda_integrator.v%cw_x_q <= ovf_x_d_i;%cw_x_q <= 1'b0;%a copy of the X carry"
    "fast_nz%dda_counter.v%nz_d  = ~one_q;%nz_d  = 1'b1;%nz_q differs"
    "fast_one%dda_counter.v%one_d = cnt_q == Two;%one_d = 1'b0;%one_q differs"
  )
fi
export DDA_RTL=$root/rtl
status=0
for m in "${mutants[@]}"; do
  IFS='%' read -r name file from to text <<< "$m"
  dir="$build/formal_mutants/$impl/$name"
  rm -rf "$dir"
  mkdir -p "$dir"
  "$root/scripts/rtl-files.sh" "$root/rtl/dda_core.f" | xargs cp -t "$dir/"
  grep -qF "$from" "$dir/$file" || { echo "formal-mutants: anchor not found in rtl/$file: $from" >&2; exit 1; }
  FROM=$from TO=$to perl -0pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$dir/$file"
  echo "mutant $name ($file):"
  "$root/scripts/formal.sh" --impl "$impl" --acc 8 --cnt 4 --depth 8 --rtl "$dir" --expect-fail "$text" props |
    grep -v "^formal props" || status=1
done
exit $status
