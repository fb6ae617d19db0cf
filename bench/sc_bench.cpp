// SPDX-License-Identifier: Apache-2.0
// scripts/bench: the SystemC model's speed (see bench_main.hpp).
#include <systemc>

#include "bench/bench_main.hpp"
#include "tb/engines/sc_harness.hpp"

int main(int argc, char* argv[]) {
  dda::sc::ScHarness h;
  return dda::bench_main(&h, argc, argv);
}

int sc_main(int argc, char* argv[]) { return main(argc, argv); }
