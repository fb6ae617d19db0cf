// SPDX-License-Identifier: Apache-2.0
// The pacer's reference model (model/motion/pacer.hpp) driving the golden datapath clock
// by clock: the path speed held along lines, circles and ellipses (the feed error at
// every cruise iteration, from the pace and the DDA's exact velocity), the acceleration
// measured from the step pins by the speed monitor alone, the time against the ideal
// trapezoid, the last step at the minimum speed, a hold that stops within its braking
// distance and resumes without a lost step, an override reached through the ramp and
// clamped to the piece's limit.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "host/accuracy/golden.hpp"
#include "host/planner/planner.hpp"
#include "model/motion/pacer.hpp"
#include "tb/measure/pace_report.hpp"
#include "tb/monitors/speed_monitor.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

constexpr double kClock = 40e6;

using Each = std::function<void(std::uint64_t, PaceSettings&)>;
using Watch = std::function<void(std::uint64_t, const Pacer&, double)>;
PaceResult run(const Plan& plan, double feed, double accel, double vmin, const Each& each = nullptr,
               const Watch& watch = nullptr) {
  PaceHooks h;
  h.each = each;
  h.watch = watch;
  return pace_plan(plan, PaceOptions{feed, accel, vmin, kClock}, h);
}
double steps_per_s(std::uint64_t ramp_speed) { return ramp_steps_per_s(ramp_speed, kClock); }

Plan circle(std::int64_t r) {
  ArcSpec s;
  s.a = s.b = r;
  s.preload = Preload::Half;
  s.from_theta = 0;
  s.to_theta = 0;
  return plan_arc(s);
}
Plan quarter(std::int64_t a, std::int64_t b) {
  ArcSpec s;
  s.a = a;
  s.b = b;
  s.preload = Preload::Half;
  return plan_arc(s);
}

}  // namespace

TEST_CASE("pacer: lines, circles and ellipses at a constant path speed, ramps at the acceleration", "[pacer]") {
  struct Case {
    const char* name;
    Plan plan;
    double feed, accel;
  };
  const std::vector<Case> cases = {
      {"line 20000 x 6000", plan_line(Point{}, Point{20000, 6000, 0}, Preload::Half), 2e5, 2e7},
      {"circle of radius 2000", circle(2000), 2e5, 2e7},
      {"quarter ellipse 4000 x 1000", quarter(4000, 1000), 1e5, 1e7},
      {"quarter ellipse 10000 x 1000", quarter(10000, 1000), 5e4, 5e6},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const PaceResult r = run(c.plan, c.feed, c.accel, 500);
    INFO(r.monitor.summary());
    CHECK(r.end == c.plan.to);
    REQUIRE(r.cruise_iterations > 100);
    CHECK(r.worst_cruise_error < 1e-3);
    CHECK(r.worst_speed_change <= c.accel * 1.0001);
    CHECK(r.monitor.peak_accel() < c.accel * 1.05);
    CHECK(r.monitor.peak_speed() < c.feed * 1.01);
    CHECK(r.last_speed <= 500 * 1.001);
    CHECK(r.seconds() < r.ideal_seconds * 1.02);
    CHECK(r.seconds() > r.ideal_seconds * 0.99);
    // Skipping the clocks on which only the phase moves changes nothing.
    PaceHooks every;
    every.clock_by_clock = true;
    const PaceResult slow = pace_plan(c.plan, PaceOptions{c.feed, c.accel, 500, kClock}, every);
    CHECK(slow.clocks == r.clocks);
    CHECK(slow.iterations == r.iterations);
    CHECK(slow.last_speed == r.last_speed);
    CHECK(slow.worst_cruise_error == r.worst_cruise_error);
  }
}

TEST_CASE("pacer: a hold stops within the braking distance, keeps its place and resumes", "[pacer]") {
  const Plan plan = plan_line(Point{}, Point{20000, 6000, 0}, Preload::Half);
  const double feed = 2e5, accel = 2e7;
  const std::uint64_t hold_at = 2000000, resume_at = 3000000;
  double path_at_hold = 0, speed_at_hold = 0, path_at_rest = -1;
  const PaceResult free_run = run(plan, feed, accel, 500);
  const PaceResult held = run(
      plan, feed, accel, 500,
      [&](std::uint64_t clock, PaceSettings& s) { s.hold = clock >= hold_at && clock < resume_at; },
      [&](std::uint64_t clock, const Pacer& p, double path) {
        if (clock + 1 == hold_at) {
          path_at_hold = path;
          speed_at_hold = steps_per_s(p.speed());
        }
        if (clock >= hold_at && path_at_rest < 0 && p.speed() == 0) path_at_rest = path;
      });
  INFO(held.monitor.summary());
  CHECK(held.end == plan.to);
  CHECK(held.monitor.peak_accel() < accel * 1.05);
  REQUIRE(speed_at_hold == Approx(feed).epsilon(0.001));
  REQUIRE(path_at_rest > path_at_hold);
  CHECK(path_at_rest - path_at_hold <= speed_at_hold * speed_at_hold / (2 * accel) * 1.01 + 1);
  // Ramping down from cruise and up again on the same length takes the time the hold
  // lasts more than the free run takes.
  CHECK(double(held.clocks - free_run.clocks) == Approx(double(resume_at - hold_at)).epsilon(0.01));
}

TEST_CASE("pacer: an override is reached through the ramp and clamped to the piece's limit", "[pacer]") {
  const Plan plan = plan_line(Point{}, Point{20000, 6000, 0}, Preload::Half);
  const double feed = 2e5, accel = 2e7;
  double speed_half = 0, speed_over = 0;
  const PaceResult r = run(
      plan, feed, accel, 500,
      [&](std::uint64_t clock, PaceSettings& s) {
        s.override_ = clock < 1500000 ? kOverrideOne : clock < 2500000 ? kOverrideOne / 2 : 2 * kOverrideOne;
      },
      [&](std::uint64_t clock, const Pacer& p, double) {
        if (clock == 2400000) speed_half = steps_per_s(p.speed());
        if (clock == 3000000) speed_over = steps_per_s(p.speed());
      });
  INFO(r.monitor.summary());
  CHECK(r.end == plan.to);
  CHECK(r.monitor.peak_accel() < accel * 1.05);
  CHECK(r.monitor.peak_speed() < feed * 1.01);
  CHECK(speed_half == Approx(feed / 2).epsilon(1e-6));
  CHECK(speed_over == Approx(feed).epsilon(1e-6));  // 200% clamped to the limit: the cruise speed
}

TEST_CASE("pacer: a take clamps the cruise speed in force to the new entry's limit at once", "[pacer]") {
  // Two entries by hand: the first cruises at its limit, the second's limit is half of
  // it. From the edge of the take on, the target (the held product of cruise speed and
  // override, until the new product is formed) is within the new limit, and v only
  // ramps down to it.
  Pacer p;
  Pacer::In in;
  in.advance = true;
  in.set.accel = std::uint64_t{1} << 30;  // (1/16 step/clock in 2^14 clocks)
  in.norm = NormOperands{1000, 0, 0, 1u << 20, 1u << 20};
  in.running = true;
  in.take = true;
  in.entry = PaceEntry{1u << 28, 1u << 28, 0, 1u << 30, 0};
  p.edge(in);
  in.take = false;
  for (int i = 0; i < 20000; ++i) p.edge(in);
  REQUIRE(p.cruise_speed() == std::uint64_t{1u << 28} << (kRampFrac - kSpeedFrac));
  REQUIRE(p.speed() == p.cruise_speed());
  in.take = true;
  in.entry = PaceEntry{1u << 28, 1u << 27, 0, 1u << 30, 0};
  p.edge(in);
  in.take = false;
  const std::uint64_t limit = std::uint64_t{1u << 27} << (kRampFrac - kSpeedFrac);
  CHECK(p.cruise_speed() == limit);
  CHECK(p.override_busy() > 0);  // the new product is still being formed
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t before = p.speed();
    p.edge(in);
    REQUIRE(p.target(in) <= limit);
    REQUIRE(p.speed() <= before);
  }
  CHECK(p.speed() == limit);
}
