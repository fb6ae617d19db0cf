#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Long regressions (not in the default test suite), each in lockstep with the golden
# model, random arcs back to back, some with random ce_i stalls, some reset halfway:
#   systemc  the SystemC model                       (default 2,000 arcs)
#   rtl      the RTL under Verilator (--cc)          (default 100,000 arcs, about 40 min)
#   cosim    SystemC model and RTL on one sc_clock   (default 2,000 arcs)
# usage: scripts/regress.sh [systemc|rtl|cosim|all] [arcs] [seed]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DDA_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" >/dev/null
which=${1:-all}
seed=${3:-1}
run() { "$build/bin/$1" --arcs "$2" --seed "$seed"; }
case "$which" in
  systemc) run sc_regress "${2:-2000}" ;;
  rtl) run rtl_regress "${2:-100000}" ;;
  cosim) run cosim_regress "${2:-2000}" ;;
  all) run sc_regress "${2:-2000}"; run rtl_regress "${2:-100000}"; run cosim_regress "${2:-2000}" ;;
  *) echo "usage: $0 [systemc|rtl|cosim|all] [arcs] [seed]" >&2; exit 2 ;;
esac
