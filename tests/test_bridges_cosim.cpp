// SPDX-License-Identifier: Apache-2.0
// The block behind its AXI4-Lite and SPI bridges as SystemC models (the bridged tops of
// model/systemc/dda_motion_bridged.hpp) co-simulated with the RTL every cycle (ports, block,
// core and bridge registers) and compared with the reference models, under random
// queued work that must do the same, iteration by iteration, as the same work over
// Wishbone. Every TEST_CASE is its own ctest entry and process (SystemC elaborates once).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <systemc>

#include "tb/cosim/bridge_cosim.hpp"
#include "tb/random/bus_work.hpp"
#include "tb/random/dda_random.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

using namespace dda;
using namespace dda::motion;

namespace {
void same_work(Bus bus, std::uint64_t seed, int arcs) {
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  BridgeCosim h(bus);
  const BusWork got = run_bus_work(h, bus, seed, arcs);
  ModelTarget ref(kHarnessDepthLog2);
  const BusWork want = run_bus_work(ref, Bus::wishbone, seed, arcs);
  INFO(h.cycle() << " cycles");
  CHECK(got.end == got.want);
  CHECK(got.snap == got.end);
  CHECK(got.entry_read == 0);
  CHECK(got.snap_after_write == got.snap);
  CHECK(got.irq_seen);
  CHECK(got.irq_cleared);
  CHECK(got.iterations.size() > 100);
  CHECK(compare_work(want, got) == "");
}
}  // namespace

TEST_CASE("bridges cosim: random work over AXI4-Lite, SystemC model and RTL equal every cycle, as over Wishbone",
          "[bridges][cosim]") {
  same_work(Bus::axil, test_seed(93), 8);
}

TEST_CASE("bridges cosim: random work over SPI, SystemC model and RTL equal every cycle, as over Wishbone",
          "[bridges][cosim]") {
  same_work(Bus::spi, test_seed(95), 3);  // (an SPI access takes some 300 clocks)
}
