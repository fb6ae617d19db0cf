// SPDX-License-Identifier: Apache-2.0
// Regression of the three-way co-simulation (scripts/regress.sh).
//   usage: cosim_regress [--arcs N] [--seed S]
#include <systemc>

#include "tb/cosim/cosim_harness.hpp"
#include "tb/random/regress.hpp"

int main(int argc, char* argv[]) {
  dda::cosim::CosimHarness h;
  return dda::regress_main(h, argc, argv);
}

int sc_main(int argc, char* argv[]) { return main(argc, argv); }
