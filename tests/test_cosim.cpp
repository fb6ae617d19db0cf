// SPDX-License-Identifier: Apache-2.0
// Three-way co-simulation: the SystemC model and the RTL on one clock, compared in
// every register and output every cycle, and against the golden model every iteration.
// Every TEST_CASE is its own ctest entry and process (one elaboration each).
#define CATCH_CONFIG_RUNNER
#include <systemc>

#include "tb/cosim/cosim_harness.hpp"
#include "tb/random/regress.hpp"
#include "tests/core_checks.hpp"

using namespace dda;
using namespace dda::checks;

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

TEST_CASE("cosim: paper example, both models equal every cycle and to the golden model", "[cosim]") {
  cosim::CosimHarness h;
  paper_example(h);
  CHECK(h.compared_cycles() >= 27);
}

TEST_CASE("cosim: 100 random arcs (quarter, whole, as programs give them) back to back with ce stalls and resets",
          "[cosim][random]") {
  cosim::CosimHarness h;
  const std::uint64_t seed = test_seed(51);
  INFO("seed " << seed);
  const MixedStats st = run_mixed(h, seed, 100);
  INFO(st.iterations << " iterations, " << st.cycles << " cycles");
  CHECK(st.arcs == 100);
  CHECK(st.ce_stalled > 0);
  CHECK(st.resets > 0);
  CHECK(st.line_pieces > 0);  // lines and the lines next to arcs' ends ran too
}

TEST_CASE("cosim: 40 random three-axis moves (3-D lines, third axis alone, helices) in both models",
          "[cosim][random]") {
  cosim::CosimHarness h;
  random_arcs(h, test_seed(53), 40, ArcKind::Spatial);
}

TEST_CASE("cosim: reset in the middle of an arc, then the next command", "[cosim]") {
  cosim::CosimHarness h;
  reset_midway(h);
}

TEST_CASE("cosim: empty and stalled commands end with done and err in both models", "[cosim]") {
  cosim::CosimHarness h;
  finished_and_stalled(h);
}

TEST_CASE("cosim: a negative integrand holds its axis until it turns positive", "[cosim]") {
  cosim::CosimHarness h;
  negative_integrand_holds(h);
}
