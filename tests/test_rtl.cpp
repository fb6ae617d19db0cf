// SPDX-License-Identifier: Apache-2.0
// The RTL (Verilator --cc) against the golden model, register by register, iteration by
// iteration. Each harness has its own VerilatedContext, so tests share one process.
#define CATCH_CONFIG_MAIN
#include "tb/engines/rtl_harness.hpp"
#include "tests/core_checks.hpp"

using namespace dda;
using namespace dda::checks;

TEST_CASE("rtl: paper example matches the golden model in every register", "[rtl]") {
  paper_example_with_waveform<rtl::RtlHarness>("rtl_paper");
}

// The fast implementation's own registers (hw::kFastRegisters) are in its RTL at their
// widths, and none of them is in the small one's (test_rtl_fast is this program built
// on the fast harness, with DDA_TEST_IMPL_FAST).
TEST_CASE("rtl: the fast implementation's own registers are its own", "[rtl]") {
  rtl::RtlHarness h;
  for (const auto& r : hw::kFastRegisters) {
    INFO(r.name);
#ifdef DDA_TEST_IMPL_FAST
    CHECK_NOTHROW(h.resolve(hw::SignalTable{r}));
#else
    CHECK_THROWS_AS(h.resolve(hw::SignalTable{r}), GuardError);
#endif
  }
#ifdef DDA_TEST_IMPL_FAST
  // A width that differs is found too.
  hw::Reg wrong = hw::kFastRegisters.front();
  wrong.width -= 1;
  CHECK_THROWS_AS(h.resolve(hw::SignalTable{wrong}), GuardError);
#endif
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

TEST_CASE("rtl: 300 random three-axis moves (3-D lines, third axis alone, helices) in lockstep", "[rtl][random]") {
  rtl::RtlHarness h;
  random_arcs(h, test_seed(47), 300, ArcKind::Spatial);
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
