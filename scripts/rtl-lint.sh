#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Verilator lint of the RTL (the core, the motion block around it with the pacer and its norm unit, the block behind
# its bus bridges) with every
# warning on; fails on any %Warning or %Error.
#   usage: scripts/rtl-lint.sh        (ctest: rtl.lint)
# Waivers, each with its reason, live in rtl/lint.vlt.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
verilator=${VERILATOR:-verilator}
cd "$root"
export DDA_RTL=$root/rtl
out=$("$verilator" --lint-only -Wall -Irtl rtl/lint.vlt -f rtl/dda_core.f --top-module dda_core 2>&1)
rc=$?
# The motion block (the core on a Wishbone bus) on top of it.
out2=$("$verilator" --lint-only -Wall -Irtl rtl/lint.vlt -f rtl/dda_motion.f --top-module dda_motion 2>&1)
rc2=$?
out=$out$out2
[ $rc2 -eq 0 ] || rc=$rc2
# The block behind its AXI4-Lite and SPI bridges.
for top in dda_motion_axil dda_motion_spi; do
  out3=$("$verilator" --lint-only -Wall -Irtl rtl/lint.vlt -f rtl/$top.f --top-module $top 2>&1)
  rc3=$?
  out=$out$out3
  [ $rc3 -eq 0 ] || rc=$rc3
done
# The bridges alone in the wrapper of their place-and-route figures, each bus.
for bus in axil spi; do
  out3=$("$verilator" --lint-only -Wall -Irtl rtl/lint.vlt rtl/dda_axil.v rtl/dda_spi.v rtl/fpga/dda_bridge_top.v \
    --top-module dda_bridge_top -GBus="\"$bus\"" 2>&1)
  rc3=$?
  out=$out$out3
  [ $rc3 -eq 0 ] || rc=$rc3
done
# Every source of rtl/ at once, as a user lints the folder (the bridged tops waive
# MULTITOP in their sources).
out3=$("$verilator" --lint-only -Wall -Irtl rtl/*.v 2>&1)
rc3=$?
out=$out$out3
[ $rc3 -eq 0 ] || rc=$rc3
[ -n "$out" ] && echo "$out"
if [ $rc -ne 0 ] || echo "$out" | grep -Eq '%(Warning|Error)'; then
  echo "rtl-lint: FAIL (verilator exit $rc)" >&2
  exit 1
fi
echo "rtl-lint: PASS: verilator --lint-only -Wall, no warning"
