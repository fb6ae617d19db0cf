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

#include "accuracy/golden.hpp"
#include "motion/pacer.hpp"
#include "motion/speed_monitor.hpp"
#include "planner/planner.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

constexpr double kClock = 40e6;

std::uint32_t speed_field(double steps_per_s) {
  return std::uint32_t(std::llround(steps_per_s / kClock * 4294967296.0));
}
std::uint64_t accel_field(double steps_per_s2) {
  return std::uint64_t(std::llround(steps_per_s2 / (kClock * kClock) * std::ldexp(1.0, kRampFrac)));
}
double steps_per_s(std::uint64_t ramp_speed) { return double(ramp_speed) / std::ldexp(1.0, kRampFrac) * kClock; }

// The DDA's exact speed along the path per iteration (steps), from its registers.
double exact_distance(const Command& c, const RegState& r) {
  const double vx = r.cnt_x != 0 && r.jv_x > 0 ? double(r.jv_x) : 0.0;
  const double vy = r.cnt_y != 0 && r.jv_y > 0 ? double(r.jv_y) : 0.0;
  const double vz = r.cnt_z != 0 ? double(c.jv_z) / double(c.cap_z) : 0.0;
  return std::hypot(std::hypot(vx, vy) / double(c.cap), vz);
}

struct Result {
  std::uint64_t clocks = 0;
  double path = 0;                // steps, the sum of the exact distances
  double worst_cruise_error = 0;  // |v - F| / F over the iterations at cruise
  std::uint64_t cruise_iterations = 0;
  double last_speed = 0;  // steps/s, the commanded speed at the last iteration
  Point end;
  SpeedMonitor mon;
};

// Runs the pieces back to back through the pacer (each entry's exit speed its cruise,
// the last one's 0), the core taking the next entry the clock after a piece ends; `each`
// may change the settings before every clock, `watch` sees the pacer and the path so far
// after it.
using Each = std::function<void(std::uint64_t, PaceSettings&)>;
using Watch = std::function<void(std::uint64_t, const Pacer&, double)>;
Result run(const Plan& plan, double feed, double accel, double vmin, const Each& each = nullptr,
           const Watch& watch = nullptr) {
  PaceSettings set;
  set.accel = accel_field(accel);
  set.vmin = speed_field(vmin);
  std::vector<PaceEntry> entries;
  for (std::size_t i = 0; i < plan.pieces.size(); ++i) {
    PaceEntry e;
    e.cruise = e.limit = speed_field(feed);
    e.exit = i + 1 < plan.pieces.size() ? e.cruise : 0;
    e.brake_exit = brake_distance(e.exit, set.accel);
    e.length = pace_length(plan.pieces[i].cmd);
    entries.push_back(e);
  }
  Result res{0, 0, 0, 0, 0, plan.from, SpeedMonitor(MotionLimits{kClock, feed, accel})};
  Pacer p;
  std::optional<Datapath> dp;
  std::size_t next = 0, cur = 0;
  bool stepped = false;
  for (std::uint64_t clock = 0;; ++clock) {
    Pacer::In in;
    in.advance = true;
    in.running = dp && !dp->done();
    if (in.running) {
      in.cmd = &plan.pieces[cur].cmd;
      in.regs = dp->regs();
    }
    in.take = !in.running && next < plan.pieces.size();
    if (in.take) in.entry = entries[next];
    in.next_queued = next + (in.take ? 1 : 0) < plan.pieces.size();
    if (each) each(clock, set);
    in.set = set;
    if (!in.running && !in.take) break;
    const bool it = p.iterate(in);
    std::array<bool, 3> step{}, dir{};
    if (it) {
      const double d = exact_distance(*in.cmd, in.regs);
      const double v = steps_per_s(p.speed()) / (double(p.distance()) / std::ldexp(1.0, kNormFrac)) * d;
      res.path += d;
      res.last_speed = steps_per_s(p.speed());
      if (p.speed() == p.target(in) && !p.ramping_down() && !set.hold && d > 0) {
        res.worst_cruise_error = std::max(res.worst_cruise_error, std::fabs(v - feed) / feed);
        ++res.cruise_iterations;
      }
    }
    const bool was_stepped = stepped;
    p.edge(in, was_stepped);
    stepped = false;
    if (it) {
      const Iteration r = dp->iterate();
      stepped = r.step_x || r.step_y || r.step_z;
      const Point delta = to_run_axes(Point{r.step_x ? (plan.pieces[cur].cmd.dir_x_neg ? -1 : 1) : 0,
                                            r.step_y ? (plan.pieces[cur].cmd.dir_y_neg ? -1 : 1) : 0,
                                            r.step_z ? (plan.pieces[cur].cmd.dir_z_neg ? -1 : 1) : 0},
                                      plan.pieces[cur].rot);
      res.end = res.end + delta;
      step = {delta.x != 0, delta.y != 0, delta.z != 0};
      dir = {delta.x < 0, delta.y < 0, delta.z < 0};
    }
    res.mon.edge(step, dir);
    if (in.take) {
      cur = next++;
      dp.emplace(plan.pieces[cur].cmd, Point{}, plan.pieces[cur].rot);
    }
    res.clocks = clock + 1;
    if (watch) watch(clock, p, res.path);
  }
  return res;
}

// The time of the ideal trapezoid from rest to rest over `length` at feed and accel.
double trapezoid_seconds(double length, double feed, double accel) {
  if (length * accel < feed * feed) return 2 * std::sqrt(length / accel);  // a triangle
  return length / feed + feed / accel;
}

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
    const Result r = run(c.plan, c.feed, c.accel, 500);
    INFO(r.mon.summary());
    CHECK(r.end == c.plan.to);
    REQUIRE(r.cruise_iterations > 100);
    CHECK(r.worst_cruise_error < 1e-3);
    CHECK(r.mon.peak_accel() < c.accel * 1.05);
    CHECK(r.mon.peak_speed() < c.feed * 1.01);
    CHECK(r.last_speed <= 500 * 1.001);
    const double ideal = trapezoid_seconds(r.path, c.feed, c.accel);
    CHECK(double(r.clocks) / kClock < ideal * 1.02);
    CHECK(double(r.clocks) / kClock > ideal * 0.99);
  }
}

TEST_CASE("pacer: a hold stops within the braking distance, keeps its place and resumes", "[pacer]") {
  const Plan plan = plan_line(Point{}, Point{20000, 6000, 0}, Preload::Half);
  const double feed = 2e5, accel = 2e7;
  const std::uint64_t hold_at = 2000000, resume_at = 3000000;
  double path_at_hold = 0, speed_at_hold = 0, path_at_rest = -1;
  const Result free_run = run(plan, feed, accel, 500);
  const Result held = run(
      plan, feed, accel, 500,
      [&](std::uint64_t clock, PaceSettings& s) { s.hold = clock >= hold_at && clock < resume_at; },
      [&](std::uint64_t clock, const Pacer& p, double path) {
        if (clock + 1 == hold_at) {
          path_at_hold = path;
          speed_at_hold = steps_per_s(p.speed());
        }
        if (clock >= hold_at && path_at_rest < 0 && p.speed() == 0) path_at_rest = path;
      });
  INFO(held.mon.summary());
  CHECK(held.end == plan.to);
  CHECK(held.mon.peak_accel() < accel * 1.05);
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
  const Result r = run(
      plan, feed, accel, 500,
      [&](std::uint64_t clock, PaceSettings& s) {
        s.override_ = clock < 1500000 ? kOverrideOne : clock < 2500000 ? kOverrideOne / 2 : 2 * kOverrideOne;
      },
      [&](std::uint64_t clock, const Pacer& p, double) {
        if (clock == 2400000) speed_half = steps_per_s(p.speed());
        if (clock == 3000000) speed_over = steps_per_s(p.speed());
      });
  INFO(r.mon.summary());
  CHECK(r.end == plan.to);
  CHECK(r.mon.peak_accel() < accel * 1.05);
  CHECK(r.mon.peak_speed() < feed * 1.01);
  CHECK(speed_half == Approx(feed / 2).epsilon(1e-6));
  CHECK(speed_over == Approx(feed).epsilon(1e-6));  // 200% clamped to the limit: the cruise speed
}
