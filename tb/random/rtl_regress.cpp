// SPDX-License-Identifier: Apache-2.0
// Regression of the RTL (Verilator --cc) against the golden model (scripts/regress.sh).
//   usage: rtl_regress [--arcs N] [--seed S]
#include "tb/engines/rtl_harness.hpp"
#include "tb/random/regress.hpp"

int main(int argc, char* argv[]) {
  dda::rtl::RtlHarness h;
  return dda::regress_main(h, argc, argv);
}
