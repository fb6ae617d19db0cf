// SPDX-License-Identifier: Apache-2.0
// The RTL (Verilator --cc) against the golden model, register by register, iteration by
// iteration. Each harness has its own VerilatedContext, so tests share one process.
#define CATCH_CONFIG_MAIN
#include "core_checks.hpp"
#include "rtl_harness.hpp"

using namespace dda;
using namespace dda::checks;

TEST_CASE("rtl: paper example matches the golden model in every register", "[rtl]") {
  paper_example_with_waveform<rtl::RtlHarness>("rtl_paper");
}

TEST_CASE("rtl: 1,000 random arcs back to back in lockstep with the golden model", "[rtl][random]") {
  rtl::RtlHarness h;
  random_arcs(h, test_seed(41), 1000);
}

TEST_CASE("rtl: 300 random whole-ellipse arcs (every quadrant, both directions) in lockstep", "[rtl][random]") {
  rtl::RtlHarness h;
  random_arcs(h, test_seed(43), 300, ArcKind::Whole);
}

TEST_CASE("rtl: 300 random arcs as part programs give them (lattice ends, full turns, lines) in lockstep",
          "[rtl][random]") {
  rtl::RtlHarness h;
  random_arcs(h, test_seed(45), 300, ArcKind::Program);
}

TEST_CASE("rtl: a random ce pattern stretches the same pulse sequence", "[rtl][random]") {
  rtl::RtlHarness h;
  ce_stretch(h, test_seed(6), 40);
}

TEST_CASE("rtl: reset in the middle of an arc returns to idle, next command runs", "[rtl]") {
  rtl::RtlHarness h;
  reset_midway(h);
}

TEST_CASE("rtl: empty and stalled commands end with done and err", "[rtl]") {
  rtl::RtlHarness h;
  finished_and_stalled(h);
}

TEST_CASE("rtl: a negative integrand holds its axis until it turns positive", "[rtl]") {
  rtl::RtlHarness h;
  negative_integrand_holds(h);
}
