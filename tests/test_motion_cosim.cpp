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

#include "dda_random.hpp"
#include "motion_cosim.hpp"
#include "motion_mix.hpp"
#include "planner/planner.hpp"
#include "report/pace_report.hpp"
#include "speed/pace_plan.hpp"

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
  const auto e = pace_entries(cmds, speed_field(feed, clock), speed_field(vmin, clock), accel_field(accel, clock), feed,
                              accel, clock);
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
  // reversal) at 0.01 mm steps, 2000 mm/s^2 on each axis, on a 600 kHz block.
  std::ifstream in(std::string(DDA_EXAMPLES_DIR) + "/feeds.ngc");
  REQUIRE(in);
  program::ReadOptions read;
  program::LatticeOptions lattice;
  lattice.step = 10000;
  speed::MachineLimits lim = speed::default_limits(program::Machine::Mill);
  for (speed::AxisLimits& a : lim.axes) a.accel = 2000;
  const speed::PlannedProgram pp = speed::plan_program_pieces(in, "feeds.ngc", read, lattice, lim);
  const speed::PlannerLimits pl = speed::planner_limits(lim, program::Machine::Mill);
  const double clock = 6e5;
  const speed::PaceSetup setup = speed::pace_setup(pl, lim, lattice.step, clock);
  double top = 0;
  for (const auto& s : pp.segments) top = std::max(top, s.peak);
  MotionCosim h;
  // The pins' monitor: the path's speed and acceleration, and each axis' against its own
  // limits (vmax, and the axis' acceleration: the ramps' and the curves' together).
  MotionLimits ml{clock, top / 0.01, pl.accel / 0.01};
  for (std::size_t a = 0; a < 3; ++a) {
    ml.axis_speed[a] = lim.axes[a].vmax / 60 / 0.01;
    ml.axis_accel[a] = lim.axes[a].accel / 0.01;
  }
  SpeedWatch watch(h, ml);
  WishboneMaster m(watch, 5, true, 10);
  MotionDriver d(m, 6);
  watch.set_reset(false);
  m.idle(2);
  watch.set_reset(true);
  d.set_pacing(std::uint32_t(setup.accel), setup.vmin);
  d.preset(pp.plan.from);
  for (std::size_t i = 0; i < pp.plan.pieces.size(); ++i) {
    const Piece& pc = pp.plan.pieces[i];
    d.queue(pc.cmd, 0, pc.rot, speed::pace_entry(pp.segments[i], pc, setup));
  }
  d.drain();
  CHECK(d.position() == pp.plan.to);
  INFO(watch.monitor().summary());
  CHECK(watch.monitor().peak_speed() > 0.9 * top / 0.01);
  WARN(watch.monitor().summary() << "; per axis: peak acceleration X " << watch.monitor().peak_axis_accel()[0] << ", Y "
                                 << watch.monitor().peak_axis_accel()[1] << " steps/s^2");
}
