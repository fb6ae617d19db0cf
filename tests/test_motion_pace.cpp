// SPDX-License-Identifier: Apache-2.0
// The motion block pacing its entries (docs/design.md, "Pacing in the block"), on the
// RTL beside the reference model (every register after every edge), measured at the
// pins by the speed monitor (SpeedWatch): a paced circle at its feed and acceleration, a
// feed hold and its stopping distance, a soft stop, the watchdog, a hard stop and the
// pacing registers.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>

#include "host/driver/motion_driver.hpp"
#include "host/planner/planner.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/measure/pace_report.hpp"
#include "tb/monitors/bus_monitors.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

constexpr double kClock = 16e6;  // Hz, the nominal clock the figures below are at
constexpr double kFeed = 1e5;    // steps/s
constexpr double kAccel = 2e7;   // steps/s^2
constexpr double kVmin = 2000;   // steps/s

std::uint32_t speed_field(double steps_per_s, double clock = kClock) { return dda::speed_field(steps_per_s, clock); }
std::uint32_t accel_field(double a, double clock = kClock) { return std::uint32_t(dda::accel_field(a, clock)); }

// A run's clock, feed, acceleration and minimum speed, and the monitor's samples per
// window (0 clocks per sample: the monitor's own choice).
struct Rate {
  double clock = kClock, feed = kFeed, accel = kAccel, vmin = kVmin;
  int subs = 4;
  std::uint64_t sub_clocks = 0;
};

// The RTL beside the reference model, its pins watched, a master and a driver.
struct Bench {
  Rate r;
  MotionHarness h;
  SpeedWatch watch{h};
  WishboneMaster m{watch, 1, false, 0};
  MotionDriver d{m, 2, false};

  explicit Bench(const Rate& rate = Rate{}) : r(rate) {
    MotionLimits lim{r.clock, r.feed, r.accel};
    lim.subs = r.subs;
    watch.watch(lim, r.sub_clocks);
    watch.set_reset(false);
    m.idle(2);
    watch.set_reset(true);
    d.set_pacing(accel_field(r.accel, r.clock), speed_field(r.vmin, r.clock));
  }
  std::uint32_t status() { return m.read(reg_offset("STATUS")); }
  bool status_bit(std::string_view f) { return get_field("STATUS", f, status()) != 0; }
  // Queues the plan's pieces paced at the feed, from its start.
  void queue(const Plan& plan) {
    std::vector<Command> cmds;
    for (const auto& p : plan.pieces) cmds.push_back(p.cmd);
    const std::vector<PaceEntry> e =
        pace_entries(cmds, speed_field(r.feed, r.clock), speed_field(r.vmin, r.clock), accel_field(r.accel, r.clock));
    d.preset(plan.from);
    start = h.cycle();
    for (std::size_t i = 0; i < plan.pieces.size(); ++i) d.queue(plan.pieces[i].cmd, 0, plan.pieces[i].rot, e[i]);
  }
  // Seconds since the first entry was queued (after drain(): the run's time, within a
  // status poll).
  double seconds() const { return double(h.cycle() - start) / r.clock; }
  std::uint64_t start = 0;
  // How far the pins took the tool from the start (along a line from the origin: its path).
  double gone() const {
    const auto p = watch.monitor().position();
    return std::hypot(double(p[0]), double(p[1]));
  }
  void wait_for(std::string_view f, bool v) {
    for (int i = 0; i < 200000 && status_bit(f) != v; ++i) m.idle(8);
    REQUIRE(status_bit(f) == v);
  }
};

Plan line() { return plan_line(Point{}, Point{3000, 1000, 0}, Preload::Half); }
// The braking distance from the feed at the acceleration, as the targets bound a stop.
double stop_bound() { return kFeed * kFeed / (2 * kAccel) * 1.01 + 1; }
// The ideal trapezoid's time over the line (up at the acceleration to the feed, down to
// the minimum speed), which the run is to follow within 2%.
double line_ideal() { return trapezoid_seconds(std::hypot(3000.0, 1000.0), kFeed, kAccel, kVmin); }

}  // namespace

TEST_CASE("pace block: a line and a circle at their feed, the acceleration measured at the pins", "[motion][pacer]") {
  // On the line the monitor's windows (50,600 clocks, 316 steps at the feed) measure the
  // path; on a circle of radius 200 their chords cut it short, so there the monitor
  // guards the limits only.
  {
    Bench b;
    const Plan l = line();
    b.queue(l);
    b.d.drain();
    CHECK(b.d.position() == l.to);
    const SpeedMonitor& mon = b.watch.monitor();
    INFO(mon.summary());
    CHECK(mon.peak_speed() > 0.97 * kFeed);  // it reached the feed (the monitor fails a run above it)
    CHECK(mon.peak_accel() > 0.5 * kAccel);  // and ramped
    WARN("the line: " << b.seconds() << " s, the ideal trapezoid " << line_ideal() << " s, "
                      << 100 * (b.seconds() / line_ideal() - 1) << "% over");
    CHECK(std::fabs(b.seconds() / line_ideal() - 1) <= 0.02);
  }
  Bench b;
  ArcSpec s;
  s.a = s.b = 200;
  s.preload = Preload::Half;
  const Plan circle = plan_arc(s);
  b.queue(circle);
  b.d.drain();
  CHECK(b.d.position() == circle.to);
}

TEST_CASE("pace block: a feed hold stops within the braking distance, holds, resumes to the end", "[motion][pacer]") {
  Bench b;
  const Plan l = line();
  b.queue(l);
  b.m.idle(200000);  // at the feed by now (the ramp takes 80,000 clocks)
  const double at_hold = b.gone();
  const std::uint64_t hold_at = b.h.cycle();
  b.d.hold();
  CHECK(b.status_bit("holding"));
  b.wait_for("held", true);
  const double at_rest = b.gone();
  INFO("stopped " << at_rest - at_hold << " steps after the hold, bound " << stop_bound());
  CHECK(at_rest - at_hold <= stop_bound());
  CHECK(at_rest - at_hold > 0.9 * kFeed * kFeed / (2 * kAccel));  // a ramp, not a jump
  const Point held = b.d.position();
  b.m.idle(20000);
  CHECK(b.d.position() == held);
  CHECK(b.status_bit("busy"));
  const double held_s = double(b.h.cycle() - hold_at) / kClock;
  b.d.resume();
  CHECK_FALSE(b.status_bit("held"));
  b.d.drain();
  CHECK(b.d.position() == l.to);
  // The ideal: the trapezoid plus the time from the hold to the resume (a stop and a
  // start at the acceleration cost together what cruising over their distance would,
  // plus the time at rest).
  const double ideal = line_ideal() + held_s;
  WARN("the line with a feed hold: stopped " << at_rest - at_hold << " steps after the hold (bound " << stop_bound()
                                             << "), " << b.seconds() << " s, ideal " << ideal << " s, "
                                             << 100 * (b.seconds() / ideal - 1) << "% over");
  CHECK(std::fabs(b.seconds() / ideal - 1) <= 0.02);
}

TEST_CASE("pace block: a soft stop ramps to rest and flushes, the positions exact", "[motion][pacer]") {
  Bench b;
  const Plan l = line();
  b.queue(l);
  b.m.idle(200000);
  const double at_stop = b.gone();
  b.m.write(reg_offset("CTRL"), field_bit("CTRL", "soft_stop"));
  b.wait_for("stopping", false);
  const std::uint32_t st = b.status();
  CHECK(get_field("STATUS", "aborted", st));
  CHECK(get_field("STATUS", "level", st) == 0);
  CHECK_FALSE(get_field("STATUS", "busy", st));
  CHECK(b.gone() - at_stop <= stop_bound());
  const auto p = b.watch.monitor().position();  // what the pins sent, counted apart
  CHECK(b.d.position() == Point{p[0], p[1], p[2]});
}

TEST_CASE("pace block: the watchdog runs out into a soft stop, an error and an interrupt", "[motion][pacer]") {
  Bench b;
  b.m.write(reg_offset("IRQ_ENABLE"), field_bit("IRQ_ENABLE", "err"));
  const Plan l = line();
  b.queue(l);
  b.m.write(reg_offset("WATCHDOG"), 50000);
  b.m.idle(45000);
  b.m.write(reg_offset("WATCHDOG"), 100000);  // rewritten in time: no bite
  const std::uint64_t armed = b.h.cycle();
  CHECK(b.m.read(reg_offset("WATCHDOG")) == 100000);
  b.wait_for("err_watchdog", true);
  CHECK(b.h.cycle() - armed >= 100000);
  CHECK(b.h.cycle() - armed < 100000 + 200);
  CHECK(b.h.outputs().irq);
  b.wait_for("stopping", false);
  CHECK(get_field("STATUS", "aborted", b.status()));
  const auto p = b.watch.monitor().position();
  CHECK(b.d.position() == Point{p[0], p[1], p[2]});
  CHECK(b.d.position() != l.to);  // stopped on the way
}

TEST_CASE("pace block: a hard stop stops on its edge with an error, and the pacing registers", "[motion][pacer]") {
  MotionHarness h;  // (no speed watch: a hard stop is an infinite deceleration)
  WishboneMaster m{h, 1, false, 0};
  MotionDriver d{m, 2, false};
  h.set_reset(false);
  m.idle(2);
  h.set_reset(true);
  CHECK(m.read(reg_offset("OVERRIDE")) == kOverrideOne);
  d.set_override(1000);
  CHECK(m.read(reg_offset("OVERRIDE")) == 2 * kOverrideOne);  // clamped to 200%
  d.set_override(128);
  CHECK(m.read(reg_offset("OVERRIDE")) == 128);
  d.set_override(kOverrideOne);
  d.set_pacing(accel_field(kAccel), speed_field(kVmin));
  CHECK(m.read(reg_offset("ACCEL")) == accel_field(kAccel));
  CHECK(m.read(reg_offset("VMIN")) == speed_field(kVmin));
  const Plan l = line();
  std::vector<Command> cmds;
  for (const auto& p : l.pieces) cmds.push_back(p.cmd);
  const auto e = pace_entries(cmds, speed_field(kFeed), speed_field(kVmin), accel_field(kAccel));
  for (std::size_t i = 0; i < l.pieces.size(); ++i) d.queue(l.pieces[i].cmd, 0, 0, e[i]);
  m.idle(150000);
  m.write(reg_offset("CTRL"), field_bit("CTRL", "hard_stop"));
  const std::uint32_t st = m.read(reg_offset("STATUS"));
  CHECK(get_field("STATUS", "err_hard_stop", st));
  CHECK(get_field("STATUS", "err", st));
  CHECK(get_field("STATUS", "aborted", st));
  CHECK(get_field("STATUS", "level", st) == 0);
  const Point at = d.position();
  m.idle(5000);
  CHECK(d.position() == at);
  m.write(reg_offset("CTRL"), field_bit("CTRL", "clear"));
  CHECK_FALSE(get_field("STATUS", "err_hard_stop", m.read(reg_offset("STATUS"))));
}

TEST_CASE("pace block: two blocks side by side, each in its own Verilator context", "[motion][pacer]") {
  // Verilator files a model's scopes under the thread's current context: two harnesses
  // alive at once, destroyed in reverse order, deadlocked on the first one's scopes
  // (or corrupted memory) until each harness made its own context current.
  {
    Bench b1;
    Bench b2;
    b1.m.idle(100);
    b2.m.idle(100);
    CHECK(b1.status_bit("empty"));
    CHECK(b2.status_bit("empty"));
  }
  Bench b3;
  b3.queue(plan_line(Point{}, Point{30, 10, 0}, Preload::Half));
  b3.d.drain();
  CHECK(b3.d.position() == Point{30, 10, 0});
}

namespace {

// The block follows 400,000 path steps/s on a 40 MHz clock with 4e7 steps/s^2 (and the
// minimum speed a stop from which takes a step). The monitor's windows are 40 samples of
// 2,000 clocks (20 steps at the feed): a chord of 20 steps is short by 0.1% on the
// 4:1 ellipse's tightest radius, 125 steps; a window of 800 steps counts whole steps to
// 0.25% of the speed. Every window wholly at cruise (after the ramp up, before the ramp
// down, each F / A) reads the feed within 1%; the monitor fails any window above the
// feed + 1% or the acceleration + 5% (its whole-step share here: 2.5%).
void at_4e5(const char* name, const Plan& plan) {
  Rate r;
  r.clock = 40e6;
  r.feed = 4e5;
  r.accel = 4e7;
  r.vmin = std::sqrt(2 * r.accel);
  r.subs = 40;
  r.sub_clocks = 2000;
  Bench b(r);
  b.queue(plan);
  b.d.drain();
  CHECK(b.d.position() == plan.to);
  const SpeedMonitor& mon = b.watch.monitor();
  INFO(mon.summary());
  const double t_win = double(std::uint64_t(r.subs) * r.sub_clocks) / r.clock, ramp = 1.02 * r.feed / r.accel;
  double first = -1, last = -1;
  for (const auto& s : mon.samples()) {
    if (s.speed > 0 && first < 0) first = s.t;
    if (s.speed > 0) last = s.t;
  }
  int cruise = 0;
  double low = HUGE_VAL, high = 0;
  for (const auto& s : mon.samples()) {
    if (s.t - t_win < first + ramp || s.t > last - t_win - ramp) continue;
    ++cruise;
    low = std::min(low, s.speed);
    high = std::max(high, s.speed);
  }
  WARN(name << ": " << cruise << " windows at cruise, " << low << " to " << high << " steps/s; peak acceleration "
            << mon.peak_accel() / r.accel << " A; " << b.seconds() << " s");
  CHECK(cruise > 100);
  CHECK(low >= 0.99 * r.feed);
  CHECK(high <= 1.01 * r.feed);
}

ArcSpec full_ellipse(std::int64_t a, std::int64_t b) {
  ArcSpec s;
  s.a = a;
  s.b = b;
  s.preload = Preload::Half;
  s.from = s.to = Point{a, 0, 0};
  return s;
}

}  // namespace

TEST_CASE("pace block: 4e5 steps/s at 40 MHz on a full circle of radius 2000, at the pins", "[motion][pacer]") {
  at_4e5("the circle of radius 2000", plan_arc(full_ellipse(2000, 2000)));
}

TEST_CASE("pace block: 4e5 steps/s at 40 MHz on a full ellipse 2000 x 500, at the pins", "[motion][pacer]") {
  at_4e5("the ellipse 2000 x 500", plan_arc(full_ellipse(2000, 500)));
}

TEST_CASE("pace block: 4e5 steps/s at 40 MHz on a line 8000 x 2400, at the pins", "[motion][pacer]") {
  at_4e5("the line 8000 x 2400", plan_line(Point{}, Point{8000, 2400, 0}, Preload::Half));
}
