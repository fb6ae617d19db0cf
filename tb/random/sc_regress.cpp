// SPDX-License-Identifier: Apache-2.0
// Regression of the SystemC model against the golden model (scripts/regress.sh).
//   usage: sc_regress [--arcs N] [--seed S]
#include <systemc>

#include "tb/engines/sc_harness.hpp"
#include "tb/random/regress.hpp"

int main(int argc, char* argv[]) {
  dda::sc::ScHarness h;
  return dda::regress_main(h, argc, argv);
}

int sc_main(int argc, char* argv[]) { return main(argc, argv); }
