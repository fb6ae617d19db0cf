// SPDX-License-Identifier: Apache-2.0
// The motion block's SystemC model and RTL co-simulated every cycle (ports, block
// registers, the core's registers) and compared with the block's reference model, under
// random queued work with aborts, resets, partial commits and overflows; the position
// counters end on every batch's end point; a paced line with a feed hold, measured at
// the pins by the speed monitor; a part program at its planned speeds. Every TEST_CASE is its own ctest entry and
// process (SystemC elaborates once).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <systemc>

#include "host/driver/motion_driver.hpp"
#include "host/planner/planner.hpp"
#include "host/speed/pace_plan.hpp"
#include "tb/cosim/motion_cosim.hpp"
#include "tb/cosim/paced_program.hpp"
#include "tb/measure/pace_report.hpp"
#include "tb/monitors/bus_monitors.hpp"
#include "tb/random/dda_random.hpp"
#include "tb/random/motion_mix.hpp"

#include <fstream>

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

using namespace dda;
using namespace dda::motion;

TEST_CASE("motion cosim: 60 random arcs queued on classic cycles, SystemC model and RTL equal every cycle",
          "[motion][cosim]") {
  const std::uint64_t seed = test_seed(71);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  const MixStats st = run_motion_mix(h, seed, 60, false);
  INFO(st.pieces << " pieces, " << h.cycle() << " cycles");
  CHECK(st.arcs == 60);
  CHECK(st.position_checks > 0);
  CHECK(st.piece_checks > 0);
  CHECK(st.pulses_z > 0);      // the third axis' stage ran
  CHECK(st.paced_pieces > 0);  // the pacer ran, with a hold and an override change
  CHECK(st.glitches > 0);      // glitches on the machine's inputs, ignored
}

TEST_CASE("motion cosim: 60 random arcs queued on pipelined cycles, SystemC model and RTL equal every cycle",
          "[motion][cosim]") {
  const std::uint64_t seed = test_seed(73);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  const MixStats st = run_motion_mix(h, seed, 60, true);
  CHECK(st.arcs == 60);
  CHECK(st.position_checks > 0);
  CHECK(st.piece_checks > 0);
  CHECK(st.pulses_z > 0);      // the third axis' stage ran
  CHECK(st.paced_pieces > 0);  // the pacer ran, with a hold and an override change
  CHECK(st.glitches > 0);      // glitches on the machine's inputs, ignored
}

TEST_CASE("motion cosim: a paced line with a feed hold, SystemC model and RTL equal, the speed at the pins",
          "[motion][cosim][pacer]") {
  const double clock = 16e6, feed = 1e5, accel = 2e7, vmin = 2000;
  MotionCosim h;
  SpeedWatch watch(h, MotionLimits{clock, feed, accel});
  WishboneMaster m(watch, 3, true, 10);
  MotionDriver d(m, 4);
  watch.set_reset(false);
  m.idle(2);
  watch.set_reset(true);
  d.set_pacing(std::uint32_t(accel_field(accel, clock)), speed_field(vmin, clock));
  const Plan line = plan_line(Point{}, Point{2000, 800, 0}, Preload::Half);
  std::vector<Command> cmds;
  for (const auto& p : line.pieces) cmds.push_back(p.cmd);
  const auto e = pace_entries(cmds, speed_field(feed, clock), speed_field(vmin, clock), accel_field(accel, clock));
  d.preset(line.from);
  for (std::size_t i = 0; i < line.pieces.size(); ++i) d.queue(line.pieces[i].cmd, 0, 0, e[i]);
  m.idle(120000);
  d.hold();
  m.idle(100000);  // the ramp down from the feed takes 80,000 clocks
  CHECK(get_field("STATUS", "held", m.read(reg_offset("STATUS"))));
  d.resume();
  d.drain();
  CHECK(d.position() == line.to);
  INFO(watch.monitor().summary());
  CHECK(watch.monitor().peak_speed() > 0.97 * feed);
}

TEST_CASE("motion cosim: a program at its planned speeds, SystemC model and RTL equal, the speed at the pins",
          "[motion][cosim][pacer][speed]") {
  // examples/feeds.ngc (a corner, an arc, an ellipse cut for its curvature, a dwell, a
  // reversal) at 0.02 mm steps, 2000 mm/s^2 on each axis, on a 600 kHz block (the
  // slowest clock that follows the plan at that step is 374,767 Hz).
  std::ifstream in(std::string(DDA_EXAMPLES_DIR) + "/feeds.ngc");
  REQUIRE(in);
  program::ReadOptions read;
  program::LatticeOptions lattice;
  lattice.step = 20000;
  speed::MachineLimits lim = speed::default_limits(program::Machine::Mill);
  for (speed::AxisLimits& a : lim.axes) a.accel = 2000;
  const speed::PlannedProgram pp = speed::plan_program_pieces(in, "feeds.ngc", read, lattice, lim);
  const speed::PlannerLimits pl = speed::planner_limits(lim, program::Machine::Mill);
  const double clock = 6e5;
  const speed::ProgramPacing pace = speed::program_pacing(pp, pl, lim, lattice.step, clock);
  // The pins' monitor: the path's speed and acceleration, and each axis' against its own
  // limits (vmax, and the axis' acceleration: the ramps' and the curves' together).
  const MotionLimits ml = pin_limits(pp, pl, lim, 0.02, clock);
  MotionCosim h;
  PacedRunOptions opt;
  opt.seed = 5;
  opt.pipelined = true;
  const PacedRun run = run_paced_program(h, pp, pace, ml, opt);
  CHECK(run.position == pp.plan.to);
  INFO(run.monitor.summary());
  CHECK(run.monitor.peak_speed() > 0.9 * ml.max_speed);
  WARN(run.monitor.summary() << "; per axis: peak acceleration X " << run.monitor.peak_axis_accel()[0] << ", Y "
                             << run.monitor.peak_axis_accel()[1] << " steps/s^2");
}
