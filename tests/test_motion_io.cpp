// SPDX-License-Identifier: Apache-2.0
// The motion block's machine inputs (docs/design.md, "Machine inputs"): the scenarios of
// tb/scenarios/io_scenarios.hpp (an E-stop in the middle of a piece, limits in both stop
// modes, homing on each axis, a probing move, the snapshot while two axes run, glitches
// shorter than the filter) and the block at the ends of its ranges (a queue overflow,
// each limit, every field at its full width) on a simulated machine whose switches and
// probe follow the pulses the block sends. The RTL runs in lockstep with the reference model
// (MotionHarness) and, in the cases named "three engines", with the SystemC model too
// (MotionCosim); every check of a scenario is a CHECK here.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <systemc>

#include "tb/cosim/motion_cosim.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/scenarios/io_scenarios.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

using namespace dda;
using namespace dda::motion;

namespace {

void run(BusTarget& block, std::string_view name) {
  const IoScenario* s = find_io_scenario(name);
  REQUIRE(s != nullptr);
  INFO("scenario " << name);
  s->run(block, Expect([](bool ok, const std::string& what) {
           INFO(what);
           CHECK(ok);
         }));
}

}  // namespace

TEST_CASE("io: an E-stop in the middle of a piece stops within the filter's delay and stays stopped", "[io]") {
  MotionHarness h;
  run(h, "estop");
}

TEST_CASE("io: three engines: an E-stop in the middle of a piece", "[io]") {
  MotionCosim c;
  run(c, "estop");
}

TEST_CASE("io: a limit hit during a move stops before any pulse toward it (hard stop)", "[io]") {
  MotionHarness h;
  run(h, "limit-hard");
}

TEST_CASE("io: a limit hit during a paced move ramps down at ACCEL (limit_decel)", "[io]") {
  MotionHarness h;
  run(h, "limit-decel");
}

TEST_CASE("io: homing each axis sets the position at the switch's edge", "[io]") {
  MotionHarness h;
  run(h, "homing");
}

TEST_CASE("io: a probing move stops on the probe and reports the position at contact", "[io]") {
  MotionHarness h;
  run(h, "probing");
}

TEST_CASE("io: the snapshot while two axes run holds one clock's positions, level and count", "[io]") {
  MotionHarness h;
  run(h, "snapshot");
}

TEST_CASE("io: pulses shorter than the filter are ignored on every input", "[io]") {
  MotionHarness h;
  run(h, "glitches");
}

TEST_CASE("io: three engines: limits in both modes", "[io]") {
  MotionCosim c;
  run(c, "limit-hard");
  run(c, "limit-decel");
}

TEST_CASE("io: three engines: homing, probing, the snapshot and glitches", "[io]") {
  MotionCosim c;
  for (const char* s : {"homing", "probing", "snapshot", "glitches"}) run(c, s);
}

TEST_CASE("io: a queue filled to its depth refuses one entry more (err_overflow) and runs the rest", "[io]") {
  MotionHarness h;
  run(h, "overflow");
}

TEST_CASE("io: each of the six limits stops a move toward it, and the move away runs", "[io]") {
  MotionHarness h;
  run(h, "limits");
}

TEST_CASE("io: every register, position, command field, speed, filter and timing at its full width", "[io]") {
  MotionHarness h;
  run(h, "ranges");
}

TEST_CASE("io: three engines: the queue overflow, the six limits and the full widths", "[io]") {
  MotionCosim c;
  for (const char* s : {"overflow", "limits", "ranges"}) run(c, s);
}

TEST_CASE("io: a failed check of a scenario is reported", "[io]") {
  // The reference model alone, with the E-stop held pressed from the start: the
  // scenario's first move never gets past X = 400 (the block stays stopped), so it ends
  // in an error rather than passing.
  struct Pressed : ModelTarget {
    void set_pins(const MachinePins& p) override {
      MachinePins q = p;
      q.estop_n = false;
      ModelTarget::set_pins(q);
    }
  } pressed;
  int failed = 0;
  CHECK_THROWS_WITH(
      find_io_scenario("estop")->run(pressed, Expect([&](bool ok, const std::string&) { failed += !ok; })),
      Catch::Contains("X past 400"));
  CHECK(find_io_scenario("no-such") == nullptr);
}
