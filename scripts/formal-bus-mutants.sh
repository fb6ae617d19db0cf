#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Each bus proof fails on a mutant of its RTL (scripts/formal-bus.sh --expect-fail): a
# fault injected into a copy of rtl/ that the proof must find from reset within the
# depth given.
#   usage: scripts/formal-bus-mutants.sh   (ctest formal.bus.mutants)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
# job % depth % file % from % to % what the mutant breaks
mutants=(
  "wb%4%dda_motion.v%assign wb_stall_o = ack_q;%assign wb_stall_o = 1'b0;%a request taken in its ack cycle"
  "axil%6%dda_axil.v%wire can_wr = aw_q & w_q & ~bvalid_q;%wire can_wr = aw_q & ~bvalid_q;%a write before its data"
  "axil%10%dda_axil.v%if (s_bready_i) bvalid_q <= 1'b0;%bvalid_q <= 1'b0;%a write response dropped before it is taken"
  "spi%12%dda_spi.v%if (whole && !cyc_q) begin%if (!cyc_q) begin%an access for a frame that is not whole"
  "spi%6%dda_spi.v%sck_q  <= {sck_q[1], sck_q[0], spi_sck_i};%sck_q  <= {sck_q[1], spi_sck_i, spi_sck_i};%SCK through one flip-flop"
  "stepdir%10%dda_stepdir.v%wire fall   = step_q & tf_ge_len;%wire fall   = step_q & (tf_q + One >= len);%a pulse a cycle short of steplen"
  "stepdir%10%dda_stepdir.v%wire [TW-1:0] space = stepspace_i == '0 ? One : stepspace_i;%wire [TW-1:0] space = stepspace_i <= One ? One : stepspace_i - One;%a pulse a cycle early after the last"
  "stepdir%10%dda_stepdir.v%(change ? setup0 : ts_ge_setup)%(change ? 1'b1 : ts_ge_setup)%a pulse with the direction it turns to"
  "stepdir%10%dda_stepdir.v%wire dir_ok = step_q ? (fall & hold0) : tf_ge_hold;%wire dir_ok = step_q ? fall : tf_ge_hold;%a turn on the falling edge whatever dirhold"
  "stepdir%10%dda_stepdir.v%pend_q <= ~flush_i & pend_d;%pend_q <= ~flush_i & step_i;%a waiting step dropped"
  "stepdir%10%dda_stepdir.v%wire          pdir_d = step_i ? dir_i : pdir_q;%wire          pdir_d = dir_i;%a waiting step's direction lost"
  "stepdir%10%dda_stepdir.v%assign hold_o     = pend_d & ~rise_n;%assign hold_o     = pend_d & ~rise;%the core held when its step could go"
  "stepdir%10%dda_stepdir.v%assign hold_o     = pend_d & ~rise_n;%assign hold_o     = 1'b0;%the core never held"
)
status=0
for m in "${mutants[@]}"; do
  IFS='%' read -r job depth file from to what <<< "$m"
  dir=$build/formal_bus_mutants/$job-${file%.v}-$(echo "$from" | md5sum | cut -c1-8)
  rm -rf "$dir"
  mkdir -p "$dir"
  cp "$root"/rtl/*.v "$root"/rtl/*.vh "$dir/"
  grep -qF "$from" "$dir/$file" || { echo "formal-bus-mutants: anchor not found in rtl/$file: $from" >&2; exit 1; }
  FROM=$from TO=$to perl -0pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$dir/$file"
  echo "mutant of rtl/$file ($what):"
  "$root/scripts/formal-bus.sh" --depth "$depth" --rtl "$dir" --expect-fail "$job" || status=1
done
exit $status
