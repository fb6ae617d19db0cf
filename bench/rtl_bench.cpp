// SPDX-License-Identifier: Apache-2.0
// scripts/bench: the Verilated RTL's speed, tracing off (see bench_main.hpp).
#include "bench/bench_main.hpp"
#include "tb/engines/rtl_harness.hpp"

int main(int argc, char* argv[]) {
  dda::rtl::RtlHarness h;
  return dda::bench_main(&h, argc, argv);
}
