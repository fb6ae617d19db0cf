#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The RTL's assertions fire: for each assertion a mutant (a fault injected into a copy of
# rtl/) on which the paper's vector set must end, under Icarus and under Verilator --assert, with the
# assertion that guards against that fault (not with a vector MISMATCH: each fault
# changes nothing before the edge where its assertion fires).
#   usage: scripts/assert-mutants.sh VECTOR_SET_DIR   (ctest rtl.assertions_fire)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
[ $# -eq 1 ] || { echo "usage: $0 VECTOR_SET_DIR" >&2; exit 2; }
set_dir=$1

# name%file%anchor%replacement%assertion message
mutants=(
  "counter_underflow%dda_counter.v%cnt_d = cnt_q - dec;%cnt_d = cnt_q - dec - {{(CntWidth-1){1'b0}}, cnt_q == {CntWidth{1'b0}}};%ASSERTION dda_counter: a decrement at 0"
  "no_last_iteration%dda_ctrl.v%wire iterate  = run_ce & ~finished & ~stalled;%wire iterate  = run_ce & ~finished & ~stalled & ~(last_x_i & last_y_i);%ASSERTION dda_ctrl: in run with ce_i not exactly one of"
  "err_with_done%dda_ctrl.v%err_d   = stalled;%err_d   = stalled | finishing;%ASSERTION dda_ctrl: done and err together"
  "dir_without_step%dda_core.v%dir_x_d  = step_x_d ? cdir_x_q : dir_x_q;%dir_x_d  = cdir_x_q;%ASSERTION dda_core: dir_x_q changes without an X step"
  "cap_from_jr%dda_core.v%cmd_cap        = cmd_i[\`DDA_CMD_CAP_LSB%cmd_cap        = cmd_i[\`DDA_CMD_JR_X_LSB%ASSERTION dda_core: a loaded command is malformed"
)
status=0
for m in "${mutants[@]}"; do
  IFS='%' read -r name file from to message <<< "$m"
  dir="$build/assert_mutants/$name"
  rm -rf "$dir"
  mkdir -p "$dir"
  # The sources of the file list, and the headers they include.
  "$root/scripts/rtl-files.sh" "$root/rtl/dda_core.f" | xargs cp -t "$dir/"
  cp "$root"/rtl/*.vh "$dir/"
  grep -qF "$from" "$dir/$file" || { echo "assert-mutants: anchor not found in rtl/$file: $from" >&2; exit 1; }
  FROM=$from TO=$to perl -0pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$dir/$file"
  echo "mutant $name ($file):"
  "$root/scripts/vector-bench.sh" --rtl "$dir" --expect "$message" "$set_dir" || status=1
done
exit $status
