// SPDX-License-Identifier: Apache-2.0
// The motion block built without its machine inputs (motion::Build::inputs = 0;
// docs/design.md "Builds"): the reference model, the SystemC model and the RTL verilated
// with the build's parameters, side by side every cycle (MotionCosim). The block reads
// CONFIG.inputs 0, an input held active stops and latches nothing, the input registers
// read 0 and take no write; the random work of the default build runs on it (its input
// trips replaced by inputs held active that must act on nothing), and a paced line ends
// on its end point with the E-stop and every limit held active.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <systemc>

#include "host/driver/motion_driver.hpp"
#include "host/planner/planner.hpp"
#include "host/speed/pace_plan.hpp"
#include "tb/cosim/motion_cosim.hpp"
#include "tb/measure/pace_report.hpp"
#include "tb/monitors/bus_monitors.hpp"
#include "tb/random/dda_random.hpp"
#include "tb/random/motion_mix.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

using namespace dda;
using namespace dda::motion;

namespace {

// Every input active at the pins: the E-stop low, the others high.
MachinePins all_active() {
  MachinePins p;
  p.estop_n = false;
  p.limit = 0x3F;
  p.home = 0x7;
  p.probe = true;
  return p;
}

}  // namespace

TEST_CASE("build: without the inputs, the three engines equal and an active input acts on nothing",
          "[motion][cosim][build]") {
  STATIC_REQUIRE(!kHarnessInputs);
  MotionCosim h;
  WishboneMaster m(h, 3, true, 10);
  MotionDriver d(m, 4);
  h.set_reset(false);
  m.idle(2);
  h.set_reset(true);
  m.idle(2);
  CHECK(get_field("CONFIG", "inputs", d.read("CONFIG")) == 0);
  CHECK(get_field("CONFIG", "depth_log2", d.read("CONFIG")) == std::uint32_t(kHarnessDepthLog2));
  // The input registers take no write and read 0; CTRL.snapshot and probe_arm do nothing.
  d.set_inputs(0x7FF, 5, 3, 0x1F, 1);
  for (const char* r : {"IN_POLARITY", "IN_FILTER", "IN_MODE"}) {
    INFO(r);
    CHECK(d.read(r) == 0);
  }
  d.preset(Point{10, -20, 30});
  d.arm_probe();
  const MotionDriver::Snapshot s = d.snapshot();
  CHECK(s.pos == Point{});
  CHECK(d.read("SNAP_CYCLE") == 0);
  // A paced line runs to its end with every input active from the start.
  const double clock = 16e6, feed = 1e5, accel = 2e7, vmin = 2000;
  h.set_pins(all_active());
  d.set_pacing(std::uint32_t(accel_field(accel, clock)), speed_field(vmin, clock));
  const Plan line = plan_line(Point{10, -20, 30}, Point{1010, 380, 30}, Preload::Half);
  std::vector<Command> cmds;
  for (const auto& p : line.pieces) cmds.push_back(p.cmd);
  const auto e = pace_entries(cmds, speed_field(feed, clock), speed_field(vmin, clock), accel_field(accel, clock));
  for (std::size_t i = 0; i < line.pieces.size(); ++i) d.queue(line.pieces[i].cmd, 0, 0, e[i]);
  d.drain();
  CHECK(d.position() == line.to);
  const std::uint32_t st = d.read("STATUS");
  for (const char* f : {"err", "aborted", "err_estop", "err_limit", "probed", "probe_armed"}) {
    INFO(f);
    CHECK(get_field("STATUS", f, st) == 0);
  }
  for (const char* r : {"INPUTS", "TRIP", "LATCH_X", "PROBE_X"}) {
    INFO(r);
    CHECK(d.read(r) == 0);
  }
}

TEST_CASE("build: without the inputs, 40 random arcs, the three engines equal every cycle", "[motion][cosim][build]") {
  const std::uint64_t seed = test_seed(79);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  const MixStats st = run_motion_mix(h, seed, 40, true);
  INFO(st.pieces << " pieces, " << h.cycle() << " cycles");
  CHECK(st.arcs == 40);
  CHECK(st.position_checks > 0);
  CHECK(st.paced_pieces > 0);
  CHECK(st.input_trips > 0);  // inputs held active, checked to act on nothing
}
