// SPDX-License-Identifier: Apache-2.0
// A program's planned speeds on the motion block's pacer (host/speed/pace_plan.hpp): the
// examples' pieces, with the entries the driver writes from the plan, run through the
// pacer's reference model on the golden datapath clock by clock. The speed monitor reads
// the step pins alone and fails the run on a path acceleration above the plan's (5%
// for its whole-step quantization) or a speed above the fastest piece's; every piece
// that cruises does so within 1% of its planned speed and ends (a junction, an exact
// stop, the program's end) within 1% of the exit speed it was given; the run ends on
// the program's end; and its time is the plan's within 0.5% at a fine step, 1% at a
// coarse one, and the plan's on the pacer's own entries (speed::entries_seconds: the
// DDA's lengths, rests at the minimum speed) within 0.1% and 0.2%.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "host/speed/pace_plan.hpp"
#include "tb/measure/pace_report.hpp"

using namespace dda;
using namespace dda::speed;

namespace {

struct Example {
  const char* file;
  program::Machine machine;
  const char* start;  // X,Z on a lathe, mm (X a diameter); empty: 0,0
};

PlannedProgram plan_example(const Example& e, const MachineLimits& lim, program::Length step = 1000) {
  std::ifstream in(std::string(DDA_EXAMPLES_DIR) + "/" + e.file);
  REQUIRE(in);
  program::ReadOptions read;
  read.machine = e.machine;
  if (e.machine == program::Machine::Lathe) read.start = program::start_point(e.machine, 60000000, 5000000);
  program::LatticeOptions lattice;
  lattice.step = step;
  return plan_program_pieces(in, e.file, read, lattice, lim);
}

}  // namespace

TEST_CASE("speed pace: the examples at their planned speeds on the pacer's reference model") {
  const Example examples[] = {{"mill-contour.ngc", program::Machine::Mill, ""},
                              {"circles.ngc", program::Machine::Mill, ""},
                              {"lathe-profile.ngc", program::Machine::Lathe, "60,5"},
                              {"ellipses.ngc", program::Machine::Lathe, "60,5"},
                              {"lathe-paper-native.ngc", program::Machine::Lathe, "60,5"}};
  for (const Example& e : examples) {
    INFO(e.file);
    MachineLimits lim = default_limits(e.machine);
    lim.default_feed = 100;
    const PlannedProgram pp = plan_example(e, lim);
    const PlannerLimits pl = planner_limits(lim, e.machine);
    const double clock = 40e6;
    const PaceSetup setup = pace_setup(pl, lim, 1000, clock);
    const PaceResult r = pace_program(pp, setup, pl, lim);  // (the monitor throws over a limit)
    CHECK(r.end == pp.plan.to);
    CHECK(r.worst_cruise_error < 0.01);
    CHECK(r.junctions == pp.plan.pieces.size());
    CHECK(r.worst_junction_excess < 0.01);
    const double planned = pp.totals.time - pp.totals.dwell;
    const double own = entries_seconds(program_entries(pp, setup), setup);
    WARN(e.file << ": pacer " << r.seconds() << " s, on its entries " << own << " s, plan " << planned
                << " s, cruise within " << r.worst_cruise_error << ", piece ends at most " << r.worst_junction_excess
                << " over their exit speeds, monitor " << r.monitor.summary());
    CHECK(r.seconds() == Approx(planned).epsilon(0.005));
    CHECK(r.seconds() == Approx(own).epsilon(0.001));
  }
}

TEST_CASE("speed pace: at a coarse step on just over the slowest clock, the pacer keeps to the plan") {
  // 0.05 mm steps on a slow machine (50 mm/s^2 per axis, rapids at 200 mm/min, drives
  // starting at 30 mm/min), the block clocked 5% over speed::slowest_clock: the core
  // keeps up (no backlog: the monitor's speed limit holds, the time is the plan's on the
  // DDA's path, speed::entries_seconds, within 0.2%, and the programmed one's within 1%).
  // 10% under that clock is refused.
  const Example examples[] = {{"circles.ngc", program::Machine::Mill, ""},
                              {"lines-3d.ngc", program::Machine::Mill, ""},
                              {"lathe-paper-native.ngc", program::Machine::Lathe, "60,5"}};
  for (const Example& e : examples) {
    INFO(e.file);
    MachineLimits lim = default_limits(e.machine);
    for (AxisLimits& a : lim.axes) a.accel = 50;
    lim.rapid = 200;
    lim.min_speed = 30;
    lim.default_feed = 100;
    const PlannedProgram pp = plan_example(e, lim, 50000);
    const PlannerLimits pl = planner_limits(lim, e.machine);
    const double slowest = slowest_clock(pp, pl, 0.05);
    CHECK_THROWS_WITH(program_pacing(pp, pl, lim, 50000, 0.9 * slowest),
                      Catch::Contains("the planned speeds need a clock of at least"));
    const PaceSetup setup = pace_setup(pl, lim, 50000, 1.05 * slowest);
    const PaceResult r = pace_program(pp, setup, pl, lim);  // (the monitor throws over a limit)
    CHECK(r.end == pp.plan.to);
    CHECK(r.worst_junction_excess < 0.01);
    const double planned = pp.totals.time - pp.totals.dwell;
    const double own = entries_seconds(program_entries(pp, setup), setup);
    WARN(e.file << ": slowest clock " << slowest << " Hz, pacer " << r.seconds() << " s, on its entries " << own
                << " s, plan " << planned << " s, piece ends at most " << r.worst_junction_excess
                << " over their exit speeds");
    CHECK(r.seconds() == Approx(planned).epsilon(0.01));
    CHECK(r.seconds() == Approx(own).epsilon(0.002));
  }
}

TEST_CASE("speed pace: exit speeds lowered to what the pacer's own lengths can slow down from") {
  // Four one-step pieces planned with exits of 100 steps/s (the second 20) on a longer
  // programmed path: the pacer's lengths leave room to slow from less, down to VMIN at
  // the end, each braking ending the pacer's margin before its piece's end.
  PaceSetup s;
  s.clock_hz = 1e5;
  s.step_mm = 0.05;
  s.accel = std::uint64_t(std::ldexp(1000.0 / (1e5 * 1e5), motion::kRampFrac));  // 1000 steps/s^2
  s.vmin = speed_word(0.5, s);                                                   // 10 steps/s
  std::vector<motion::PaceEntry> entries(4);
  for (motion::PaceEntry& e : entries) {
    e.cruise = e.limit = e.exit = speed_word(5, s);  // 100 steps/s
    e.length = 1u << motion::kLenFrac;               // one step
  }
  entries[3].exit = 0;
  entries[1].exit = speed_word(1, s);  // 20 steps/s: below what the rest allows
  for (motion::PaceEntry& e : entries) e.brake_exit = motion::brake_distance(e.exit, s.vmin, s.accel);
  motion::limit_exits(entries, s.vmin, s.accel);
  const auto steps_per_s = [&](std::uint32_t w) { return double(w) / std::ldexp(1.0, motion::kSpeedFrac) * 1e5; };
  // Backward from 10 steps/s over 7/8 step: sqrt(10^2 + 2 * 1000 * 7/8) = 43.0 steps/s;
  // before the piece that ends at 20, over the step and the braking from 20 to 10 less
  // the margin: sqrt(20^2 + 2000 * 7/8) = 46.4, within the 2^-kLenFrac step a braking
  // distance is rounded up to (2000 / 256 on the square of the speed, 0.2% of it).
  const double room = 1 - std::ldexp(1.0, -motion::kMarginShift);
  CHECK(steps_per_s(entries[2].exit) == Approx(std::sqrt(100 + 2000 * room)).epsilon(1e-3));
  CHECK(steps_per_s(entries[1].exit) == Approx(20).epsilon(1e-6));  // already lower: kept
  CHECK(steps_per_s(entries[0].exit) == Approx(std::sqrt(400 + 2000 * room)).epsilon(2e-3));
  CHECK(steps_per_s(entries[3].exit) == 0);
  for (std::size_t k = 0; k + 1 < entries.size(); ++k) {
    CHECK(entries[k].brake_exit == motion::brake_distance(entries[k].exit, s.vmin, s.accel));
  }
  // A piece shorter than the margin leaves its predecessor nothing above VMIN.
  entries[3].length = 16;
  entries[2].exit = speed_word(5, s);
  motion::limit_exits(entries, s.vmin, s.accel);
  CHECK(entries[2].exit == s.vmin);
}

TEST_CASE("speed pace: each block's first piece counts the cut pieces before it") {
  // feeds.ngc's ellipse is cut for its curvature: the blocks after it start later in
  // the program's pieces than before the cuts.
  std::ifstream in(std::string(DDA_EXAMPLES_DIR) + "/feeds.ngc");
  REQUIRE(in);
  program::LatticeOptions lattice;
  lattice.step = 1000;
  std::size_t pieces = 0, blocks = 0, cut = 0;
  plan_program_speeds(
      in, "feeds.ngc", program::ReadOptions{}, lattice, program::kDefaultWindow, default_limits(program::Machine::Mill),
      [](const BlockSpeeds&) {}, nullptr,
      [&](const program::BlockPlan& b) {
        CHECK(b.first_piece == pieces);
        pieces += b.plan.pieces.size();
        cut += b.plan.pieces.size() > 1;
        ++blocks;
      });
  CHECK(blocks >= 6);
  CHECK(cut > 0);
}
