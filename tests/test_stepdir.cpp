// SPDX-License-Identifier: Apache-2.0
// Step and direction timing and feed pacing in the motion block (rtl/dda_stepdir.v,
// rtl/dda_motion.v; docs/design.md "Step and direction timing"): the timing monitor names
// every violated rule; on the RTL (in lockstep with the reference model, the monitor on
// every edge) pulses are exactly steplen long and no shorter apart than the timings
// allow, an abort lets a pulse finish and counts it, polarity inverts the outputs, and a
// feed increment paces the core at feed / 2^32 iterations per clock without catching up
// after the stages held it.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

#include "host/accuracy/golden.hpp"
#include "host/driver/motion_driver.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/monitors/speed_monitor.hpp"
#include "tb/monitors/stepdir_monitor.hpp"
#include "tb/random/dda_random.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

// One piece of outputs for the synthetic checks: x's step and direction, and the
// position counter that follows the pulses (or not).
struct Sample {
  bool step, dir;
  std::int32_t pos;
};

// Runs the checker over x's samples with these timings; returns its message ("" if none).
std::string check_x(const StageTimings& t, const std::vector<Sample>& samples) {
  BlockRegs r{};
  r[breg("steplen_x_q")] = t.steplen;
  r[breg("stepspace_x_q")] = t.stepspace;
  r[breg("dirsetup_x_q")] = t.dirsetup;
  r[breg("dirhold_x_q")] = t.dirhold;
  StepDirChecker c;
  try {
    c.edge(BusIn{}, true, BlockOutputs{}, r);  // the first edge: the baseline
    for (const Sample& s : samples) {
      BlockOutputs o;
      o.step_x = s.step;
      o.dir_x = s.dir;
      r[breg("pos_x_q")] = std::uint32_t(s.pos);
      c.edge(BusIn{}, true, o, r);
    }
  } catch (const GuardError& e) {
    return e.what();
  }
  return "";
}

Plan circle(std::int64_t radius) {
  ArcSpec s;
  s.a = s.b = radius;
  s.preload = Preload::Half;
  s.from_theta = 0;
  s.to_theta = 0;  // one full turn: both axes change direction
  return plan_arc(s);
}

// The RTL harness (in lockstep with the reference model) under a timing monitor whose
// figures the tests read, driven by a Wishbone master and the firmware driver.
struct Rig {
  MotionHarness h;
  StepDirMonitor mon{h};
  WishboneMaster m;
  MotionDriver d;
  Rig(std::uint64_t seed, bool pipelined, int idle_percent) : m(mon, seed, pipelined, idle_percent), d(m, seed) {}
  // Presets the positions to the plan's start and queues its pieces (not waiting).
  void start(const Plan& p) {
    d.preset(p.from);
    for (const auto& piece : p.pieces) d.queue(piece.cmd);
  }
};

// The steps a plan makes per axis (its pieces are monotone).
std::uint64_t steps(const Plan& p, int axis) {
  std::uint64_t n = 0;
  for (const auto& q : p.pieces) n += std::uint64_t(std::abs(axis == 0 ? q.to.x - q.from.x : q.to.y - q.from.y));
  return n;
}

}  // namespace

TEST_CASE("stepdir: the timing monitor names every rule a drive's signals break", "[stepdir]") {
  const StageTimings t{3, 2, 2, 2};  // steplen, stepspace, dirsetup, dirhold
  // A good pulse: direction set 2 cycles ahead, high 3, then low.
  CHECK(
      check_x(
          t,
          {{false, true, 0}, {false, true, 0}, {true, true, -1}, {true, true, -1}, {true, true, -1}, {false, true, -1}})
          .empty());
  CHECK_THAT(check_x(t, {{false, false, 0}, {true, false, 1}, {true, false, 1}, {false, false, 1}}),
             Catch::Contains("a pulse 2 cycles long, steplen 3"));
  CHECK_THAT(check_x(t, {{true, false, 1}, {true, false, 1}, {true, false, 1}, {false, false, 1}, {true, false, 2}}),
             Catch::Contains("a pulse 1 cycles after the last one, stepspace 2"));
  CHECK_THAT(check_x(t, {{false, true, 0}, {true, true, -1}}),
             Catch::Contains("a rising step edge 1 cycles after a direction change, dirsetup 2"));
  CHECK_THAT(check_x(t, {{true, false, 1}, {true, false, 1}, {true, false, 1}, {false, false, 1}, {false, true, 1}}),
             Catch::Contains("the direction changed 1 cycles after a falling step edge, dirhold 2"));
  CHECK_THAT(check_x(t, {{true, false, 1}, {true, true, 1}}), Catch::Contains("the direction changed during a pulse"));
  CHECK_THAT(check_x(t, {{true, false, 0}}),
             Catch::Contains("the position counter is 0, the pulses that went out make it 1"));
  CHECK_THAT(check_x(t, {{false, false, 1}}),
             Catch::Contains("the position counter is 1, the pulses that went out make it 0"));
}

TEST_CASE("stepdir: a full circle with timings on the RTL: exact pulse lengths, every step out, ends on its end",
          "[stepdir]") {
  const Plan p = circle(40);
  Rig r(3, false, 10);
  auto& [h, mon, m, d] = r;
  const StageTimings tx{5, 3, 4, 2}, ty{7, 1, 0, 0};
  d.set_timings('x', tx);
  d.set_timings('y', ty);
  r.start(p);
  d.drain();
  const Point at = d.position();
  CHECK(at.x == p.to.x);
  CHECK(at.y == p.to.y);
  CHECK(mon.pulses(0) == steps(p, 0));
  CHECK(mon.pulses(1) == steps(p, 1));
  CHECK(m.read(reg_offset("DONE_COUNT")) == p.pieces.size());
  CHECK(mon.shortest(0).high == tx.steplen);
  CHECK(mon.shortest(1).high == ty.steplen);
}

TEST_CASE("stepdir: timings read back, polarity inverts the outputs, pulses are exactly steplen", "[stepdir]") {
  const Plan p = circle(25);
  Rig r(5, true, 0);
  auto& [h, mon, m, d] = r;
  d.set_timings('x', StageTimings{9, 4, 6, 3});
  d.set_timings('y', StageTimings{0, 0, 0, 0});
  CHECK(get_field("STEP_X", "steplen", m.read(reg_offset("STEP_X"))) == 9);
  CHECK(get_field("STEP_X", "stepspace", m.read(reg_offset("STEP_X"))) == 4);
  CHECK(get_field("DIR_X", "dirsetup", m.read(reg_offset("DIR_X"))) == 6);
  CHECK(get_field("DIR_X", "dirhold", m.read(reg_offset("DIR_X"))) == 3);
  d.set_polarity(field_bit("POLARITY", "step_x") | field_bit("POLARITY", "dir_y"));
  m.idle(1);
  CHECK(h.outputs().step_x);   // idle, active low
  CHECK(!h.outputs().step_y);  // idle, active high
  CHECK(h.outputs().dir_y);    // inverted
  r.start(p);
  d.drain();
  CHECK(d.position().x == p.to.x);
  CHECK(d.position().y == p.to.y);
  const auto& sx = mon.shortest(0);
  const auto& sy = mon.shortest(1);
  CHECK(sx.high == 9);  // exactly steplen: never longer, the monitor checks never shorter
  CHECK(sx.low == 4);   // the next step was waiting: out as soon as stepspace allows
  CHECK(sx.setup == 6);
  CHECK(sx.hold >= 3);  // a turn comes long after the last pulse on a circle: seen, and kept
  CHECK(sy.high == 1);  // 0 means one cycle
}

TEST_CASE("stepdir: an abort lets the pulse in progress finish its steplen and counts it", "[stepdir]") {
  const Plan p = circle(30);
  Rig r(7, false, 0);
  auto& [h, mon, m, d] = r;
  d.set_timings('x', StageTimings{400, 1, 0, 0});
  d.set_timings('y', StageTimings{400, 1, 0, 0});
  r.start(p);
  // Wait for a pulse, let it run a while, then abort.
  int guard = 0;
  while (!h.outputs().step_x && !h.outputs().step_y && ++guard < 100000) m.idle(1);
  REQUIRE(guard < 100000);
  m.idle(50);
  const bool x_high = h.outputs().step_x;
  m.write(reg_offset("CTRL"), field_bit("CTRL", "abort"));
  CHECK((x_high ? h.outputs().step_x : h.outputs().step_y));  // still high after the abort
  std::uint32_t st = m.read(reg_offset("STATUS"));
  CHECK(get_field("STATUS", "busy", st) == 1);  // the pulse is still out
  CHECK(get_field("STATUS", "level", st) == 0);
  int high = 0;
  while ((x_high ? h.outputs().step_x : h.outputs().step_y) && high < 1000) {
    m.idle(1);
    ++high;
  }
  CHECK(high > 0);
  CHECK(high < 400 - 50);
  st = m.read(reg_offset("STATUS"));
  CHECK(get_field("STATUS", "busy", st) == 0);
  // Every pulse that went out is in the position counters (the monitor checked it on
  // every edge); nothing moves any more.
  const Point at = d.position();
  CHECK(std::int64_t(mon.pulses(0) + mon.pulses(1)) > 0);
  m.idle(500);
  CHECK(d.position().x == at.x);
  CHECK(d.position().y == at.y);
  CHECK(mon.shortest(x_high ? 0 : 1).high == 400);
}

TEST_CASE("stepdir: a feed increment paces the core at feed / 2^32 iterations per clock, without bursts", "[stepdir]") {
  const Plan p = plan_arc(paper_example());
  struct Case {
    std::uint32_t feed;
    StageTimings t;
    int min_gap, max_gap;  // cycles between iterations
  };
  // 1/4 and 1/2 of the clock with zero timings: the stages never hold the core, so the
  // iterations are exactly 4 (2) cycles apart; at 3/8 of the clock 2 or 3 apart; slow drives (long pulses) hold it, and
  // then the iterations only spread out: never closer than the feed's own period.
  const std::vector<Case> cases = {{0x40000000, {}, 4, 4},
                                   {0x80000000, {}, 2, 2},
                                   {0x20000000, {}, 8, 8},
                                   {0x60000000, {}, 2, 3},
                                   {0x40000000, {30, 30, 0, 0}, 4, 1000}};
  for (const auto& c : cases) {
    INFO("feed 0x" << std::hex << c.feed << std::dec << ", steplen " << c.t.steplen);
    MotionHarness h;
    WishboneMaster m(h, 11, false, 0);
    MotionDriver d(m, 11, false);
    d.set_timings('x', c.t);
    d.set_timings('y', c.t);
    std::vector<std::uint64_t> at;
    std::uint64_t cycle = 0;
    m.each_cycle = [&] {
      if (h.model().iterated()) at.push_back(cycle);
      ++cycle;
    };
    // The whole arc queued before the core starts (ce_i low), so it never waits for the bus.
    h.set_ce(false);
    for (const auto& piece : p.pieces) d.queue(piece.cmd, c.feed);
    h.set_ce(true);
    d.drain();
    REQUIRE(at.size() > 10);
    int lo = 1 << 30, hi = 0;
    for (std::size_t i = 1; i < at.size(); ++i) {
      const int gap = int(at[i] - at[i - 1]);
      lo = std::min(lo, gap);
      hi = std::max(hi, gap);
    }
    CHECK(lo >= c.min_gap);
    CHECK(hi <= c.max_gap);
    if (c.max_gap > c.min_gap) CHECK(hi > c.min_gap);  // the slow drive did hold the core
  }
}

TEST_CASE("stepdir: the diagram of docs/design.md is what the stage does", "[stepdir]") {
  std::ifstream f(std::string(DDA_SOURCE_DIR) + "/docs/design.md", std::ios::binary);
  std::ostringstream doc;
  doc << f.rdbuf();
  const std::string want = "```\n" + stage_diagram() + "```\n";
  INFO("dda gen-params --kind stepdir-diagram prints:\n" << stage_diagram());
  CHECK(doc.str().find(want) != std::string::npos);
}

TEST_CASE("stepdir: STATUS.busy stays high from a piece's last iteration until its last pulse is out", "[stepdir]") {
  // A one-step piece, polled from every phase: whenever STATUS shows the queue empty and
  // the block idle, the position is already the end point (the core's step output in
  // the cycle after its last iteration counts as busy: found by the random mix).
  Command c;
  c.jv_y = 1;
  c.cap = 1;
  c.cnt_y = 1;
  c.dir_y_neg = true;
  for (int phase = 0; phase < 24; ++phase) {
    INFO("polling from cycle " << phase << " after the commit");
    MotionHarness h;
    WishboneMaster m(h, 13, true, 0);
    MotionDriver d(m, 13, false);
    d.set_timings('y', StageTimings{1, 1, 60, 2});  // the pulse waits 60 cycles for its direction
    d.queue(c);
    m.idle(phase);
    for (int polls = 0; polls < 100; ++polls) {
      const std::uint32_t st = m.read(reg_offset("STATUS"));
      if (get_field("STATUS", "empty", st) && !get_field("STATUS", "busy", st)) break;
    }
    CHECK(d.position().y == -1);
    CHECK(m.read(reg_offset("DONE_COUNT")) == 1);
  }
}

TEST_CASE("stepdir: timings rewritten while the axes run: every step out, every edge within the timings in force",
          "[stepdir]") {
  // A timing written on an edge acts from the next one; the block holds the core on that
  // edge (the stages' look-ahead used the old timings), so no step can find the buffer
  // full. The monitor checks each edge against the timings in force on it. A line: X
  // steps on every iteration, so the core's step after a hold comes at once.
  const Plan p = plan_line(Point{0, 0}, Point{400, -150}, Preload::Half);
  const std::uint64_t seed = test_seed(17);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  Rig r(seed, true, 0);
  auto& [h, mon, m, d] = r;
  r.start(p);
  int rewrites = 0;
  for (int guard = 0; guard < 200000; ++guard) {
    // Back-to-back writes, short and long timings in turn, so that many land while a
    // step waits for a look-ahead made with the timings just replaced.
    const auto t = [&] { return rng() % 2 ? std::uint32_t(rng() % 3) : std::uint32_t(8 + rng() % 8); };
    m.write(reg_offset(rng() % 2 ? "STEP_X" : "STEP_Y"), t() | t() << field_of("STEP_X", "stepspace").lsb);
    m.write(reg_offset(rng() % 2 ? "DIR_X" : "DIR_Y"), t() | t() << field_of("DIR_X", "dirhold").lsb);
    rewrites += 2;
    if (rng() % 4 == 0) m.idle(int(rng() % 10));
    const std::uint32_t st = m.read(reg_offset("STATUS"));
    if (get_field("STATUS", "empty", st) && !get_field("STATUS", "busy", st)) break;
  }
  CHECK(rewrites > 20);
  CHECK(d.position().x == p.to.x);
  CHECK(d.position().y == p.to.y);
  CHECK(mon.pulses(0) == steps(p, 0));
  CHECK(mon.pulses(1) == steps(p, 1));
}

namespace {

// Pins of a synthetic motion: the path length s(t) of a trapezoid (accel at a from rest
// to v, cruise, decel at a to rest) along a line at an angle or a circle, each axis'
// position the nearest whole step, one clock of step high per step. Feeds the speed
// monitor every clock; returns it.
struct Profile {
  double accel, speed, length;  // steps/s^2, steps/s, steps
  double radius = 0;            // 0: a line at `angle` degrees
  double angle = 30;
  double start_speed = 0;  // a jump at the start: the profile leaves rest at this speed
};
SpeedMonitor run_profile(const Profile& p, const MotionLimits& lim) {
  SpeedMonitor mon(lim);
  const double t_acc = (p.speed - p.start_speed) / p.accel;
  const double s_acc = (p.speed * p.speed - p.start_speed * p.start_speed) / (2 * p.accel);
  const double s_dec = p.speed * p.speed / (2 * p.accel);
  const double t_cruise = (p.length - s_acc - s_dec) / p.speed;
  const double t_end = t_acc + t_cruise + p.speed / p.accel;
  const auto path = [&](double t) {
    if (t < t_acc) return p.start_speed * t + p.accel * t * t / 2;
    if (t < t_acc + t_cruise) return s_acc + p.speed * (t - t_acc);
    const double u = std::min(t - t_acc - t_cruise, p.speed / p.accel);
    return s_acc + p.speed * t_cruise + p.speed * u - p.accel * u * u / 2;
  };
  const double th = p.angle * M_PI / 180;
  std::array<long, 3> at{};
  const auto cycles = std::uint64_t(t_end * lim.clock_hz) + std::uint64_t(lim.clock_hz / 10);
  for (std::uint64_t c = 0; c < cycles; ++c) {
    const double s = path(double(c) / lim.clock_hz);
    const double x = p.radius > 0 ? p.radius * std::cos(s / p.radius) - p.radius : s * std::cos(th);
    const double y = p.radius > 0 ? p.radius * std::sin(s / p.radius) : s * std::sin(th);
    const std::array<long, 3> want{std::lround(x), std::lround(y), 0};
    std::array<bool, 3> step{}, dir{};
    for (std::size_t a = 0; a < 3; ++a) {
      if (want[a] != at[a]) {
        step[a] = true;
        dir[a] = want[a] < at[a];
        at[a] += dir[a] ? -1 : 1;
      }
    }
    mon.edge(step, dir);
    if (std::any_of(step.begin(), step.end(), [](bool b) { return b; })) mon.edge({}, dir);  // the pulse falls
  }
  return mon;
}

}  // namespace

TEST_CASE("speed monitor: a trapezoid within its limits passes and is measured from the pins", "[stepdir]") {
  const MotionLimits lim{4e6, 2e4, 2e5};
  for (const double radius : {0.0, 3000.0}) {
    INFO("radius " << radius);
    const SpeedMonitor mon = run_profile({2e5, 2e4, 6000, radius}, lim);
    INFO(mon.summary());
    CHECK(mon.peak_speed() > 2e4 * 0.99);
    CHECK(mon.peak_speed() < 2e4 * 1.01);
    CHECK(mon.peak_accel() > 2e5 * 0.9);
    CHECK(mon.peak_accel() < 2e5 * 1.05);
    CHECK(std::abs(mon.position()[0]) + std::abs(mon.position()[1]) > 100);
  }
}

TEST_CASE("speed monitor: too fast, too hard an acceleration and a start at speed fail the run", "[stepdir]") {
  const MotionLimits lim{4e6, 2e4, 2e5};
  CHECK_THROWS_WITH(run_profile({2e5 * 1.2, 2e4, 6000}, lim), Catch::Contains("steps/s^2") && Catch::Contains("above"));
  CHECK_THROWS_WITH(run_profile({2e5, 2.2e4, 6000}, lim), Catch::Contains("steps/s over the window"));
  Profile jump{2e5, 2e4, 6000};
  jump.start_speed = 1e4;
  CHECK_THROWS_WITH(run_profile(jump, lim), Catch::Contains("steps/s^2"));
}
