// SPDX-License-Identifier: Apache-2.0
// The SystemC model against the golden model, register by register, iteration by
// iteration. Every TEST_CASE is its own ctest entry and process (one elaboration each).
#define CATCH_CONFIG_RUNNER
#include <systemc>

#include "tb/engines/sc_harness.hpp"
#include "tests/core_checks.hpp"

using namespace dda;
using namespace dda::checks;

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

namespace {
// An accumulator whose carry test is `>` instead of `>=`: a deliberately wrong
// variant, built only here.
struct FaultyIntegrator : sc::dda_integrator {
  using sc::dda_integrator::dda_integrator;
  bool carry(const sc::sum_t& s, const sc::acc_t& cap) const override { return s > cap; }
};
}  // namespace

TEST_CASE("systemc: paper example matches the golden model in every register", "[systemc]") {
  paper_example_with_waveform<sc::ScHarness>("systemc_paper");
}

TEST_CASE("systemc: 200 random arcs back to back in lockstep with the golden model", "[systemc][random]") {
  sc::ScHarness h;
  random_arcs(h, test_seed(31), 200);
}

TEST_CASE("systemc: 60 random whole-ellipse arcs in lockstep with the golden model", "[systemc][random]") {
  sc::ScHarness h;
  random_arcs(h, test_seed(33), 60, ArcKind::Whole);
}

TEST_CASE("systemc: 60 random arcs as part programs give them (lattice ends, full turns, lines) in lockstep",
          "[systemc][random]") {
  sc::ScHarness h;
  random_arcs(h, test_seed(35), 60, ArcKind::Program);
}

TEST_CASE("systemc: 60 random three-axis moves (3-D lines, third axis alone, helices) in lockstep",
          "[systemc][random]") {
  sc::ScHarness h;
  random_arcs(h, test_seed(37), 60, ArcKind::Spatial);
}

TEST_CASE("systemc: a random ce pattern stretches the same pulse sequence", "[systemc][random]") {
  sc::ScHarness h;
  ce_stretch(h, test_seed(5), 20);
}

TEST_CASE("systemc: reset in the middle of an arc returns to idle, next command runs", "[systemc]") {
  sc::ScHarness h;
  reset_midway(h);
}

TEST_CASE("systemc: empty and stalled commands end with done and err", "[systemc]") {
  sc::ScHarness h;
  finished_and_stalled(h);
}

TEST_CASE("systemc: a negative integrand holds its axis until it turns positive", "[systemc]") {
  sc::ScHarness h;
  negative_integrand_holds(h);
}

TEST_CASE("systemc: the scoreboard catches a wrong accumulator (> instead of >=)", "[systemc]") {
  // In the paper's example the Y accumulator sums to exactly the capacity at iteration 8
  // (JRY = 16.0), where the wrong variant does not carry.
  const auto faulty_y = [](const char* name) -> std::unique_ptr<sc::dda_integrator> {
    if (std::string(name) == "u_int_y") return std::make_unique<FaultyIntegrator>(name);
    return std::make_unique<sc::dda_integrator>(name);
  };
  sc::ScHarness h("", faulty_y);
  const Plan plan = paper_plan();
  const std::string message = mismatch_message(h, plan);
  INFO(message);
  CHECK(message.find("at iteration 8 (cycle 11)") != std::string::npos);
  CHECK(message.find("u_int_y.jr_q (golden 0, systemc 960)") != std::string::npos);

  // Unchecked, the variant's trace rows differ from the golden model's.
  reset_core(h);
  DriveOptions unchecked;
  unchecked.check = false;
  CHECK(trace_csv(plan, drive_arc(h, plan, unchecked).records) != trace_csv(plan, run_records(plan)));
}
