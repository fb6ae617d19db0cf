// SPDX-License-Identifier: Apache-2.0
// The pacer in RTL (rtl/dda_pace.v, with its norm unit) in lockstep with its reference
// model (motion::Pacer) while the model paces the golden datapath through planned arcs
// and lines (tb/measure/pace_report.hpp, clock by clock): on every clock the RTL gets the
// model's inputs and the core's registers, its iterate_o must equal the model's
// decision, and after every edge each of its registers the model's state: the speed,
// the phase, the braking distance, the distance to go, the entry's fields, the norm
// unit's countdown, the d it made and the d the pacer paces with, the cruise speed times
// the override and its countdown. Ramps, cruise, the last piece ending
// at the minimum speed, holds, overrides (below 100% and clamped above it), a minimum speed of 0 with no acceleration,
// a speed beyond what the norm unit lets the core step (the phase saturates).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "Vdda_pace.h"
#include "Vdda_pace___024root.h"
#include "host/accuracy/golden.hpp"
#include "host/planner/planner.hpp"
#include "model/motion/pacer.hpp"
#include "tb/measure/pace_report.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

// A 16 MHz clock keeps the runs short while the ramps span thousands of clocks (and the
// accelerations within the 32-bit ACCEL field). The feeds stay below one step per
// kNormLatency + 1 clocks (280,000 steps/s here), the fastest the norm unit lets the core
// step, but for the case that goes beyond it: the phase goes on while the core waits for
// the norm unit, and the iterations due are made up afterwards, which the speed
// monitor's windows, shorter at a slow clock, would see.
constexpr double kClock = 16e6;

std::uint64_t mask(int bits) { return bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1; }

class Lockstep {
 public:
  Lockstep() : top_(std::make_unique<Vdda_pace>()) {
    top_->rst_ni = 0;
    clock();
    top_->rst_ni = 1;
  }
  // Gives the RTL the model's inputs, compares the decision, runs the edge.
  void edge(const Pacer& p, const Pacer::In& in) {
    Vdda_pace& t = *top_;
    t.advance_i = in.advance;
    t.running_i = in.running;
    t.take_i = in.take;
    t.cruise_i = in.entry.cruise;
    t.limit_i = in.entry.limit;
    t.exit_i = in.entry.exit;
    t.length_i = in.entry.length;
    t.brake_exit_i = in.entry.brake_exit;
    t.next_queued_i = in.next_queued;
    REQUIRE(in.set.accel <= mask(kAccelWidth));
    t.accel_i = std::uint32_t(in.set.accel);
    t.vmin_i = in.set.vmin;
    t.override_i = in.set.override_;
    t.hold_i = in.set.hold;
    t.stepped_i = in.stepped;
    const NormOperands& o = in.norm;
    t.v_x_i = o.v_x;
    t.v_y_i = o.v_y;
    t.v_z_i = o.v_z;
    t.cap_i = o.cap;
    t.cap_z_i = o.cap_z;
    t.eval();
    const bool it = p.iterate(in);
    if (bool(t.iterate_o) != it) FAIL("clock " << clocks_ << ": iterate_o " << int(t.iterate_o) << ", model " << it);
    iterations_ += it;
    clock();
  }
  // Every register against the model's state after the edge.
  void compare(const Pacer& p) {
    const auto& r = *top_->rootp;
    std::string diff;
    const auto one = [&](const char* name, std::uint64_t rtl, std::uint64_t model) {
      if (rtl != model)
        diff += std::string(diff.empty() ? "" : ", ") + name + " " + std::to_string(rtl) + "/" + std::to_string(model);
    };
    one("v_q", r.dda_pace__DOT__v_q, p.speed());
    one("ph_q", r.dda_pace__DOT__ph_q, p.phase());
    one("s_q", r.dda_pace__DOT__s_q, p.brake());
    one("rem_q", r.dda_pace__DOT__rem_q, p.to_go());
    one("cruise_q", r.dda_pace__DOT__cruise_q, p.entry().cruise);
    one("limit_q", r.dda_pace__DOT__limit_q, p.entry().limit);
    one("exit_q", r.dda_pace__DOT__exit_q, p.entry().exit);
    one("brake_q", r.dda_pace__DOT__brake_q, p.entry().brake_exit);
    one("busy_q", r.dda_pace__DOT__busy_q, std::uint64_t(p.norm_busy()));
    one("pend_q", r.dda_pace__DOT__pend_q, p.pending());
    one("first_q", r.dda_pace__DOT__first_q, p.first());
    one("due_q", r.dda_pace__DOT__due_q, p.due());
    one("fresh_q", r.dda_pace__DOT__fresh_q, p.fresh());
    one("m_q", r.dda_pace__DOT__m_q, std::uint64_t(p.provisional()));
    one("cm_q", r.dda_pace__DOT__cm_q, std::uint64_t(p.correction_bits()));
    one("cd_q", r.dda_pace__DOT__cd_q, p.correction_step());
    one("d_q", r.dda_pace__DOT__d_q, p.distance());
    one("u_norm.d_q", r.dda_pace__DOT__u_norm__DOT__d_q, p.norm_distance());
    one("eff_q", r.dda_pace__DOT__eff_q, p.cruise_speed());
    one("ovr_q", r.dda_pace__DOT__ovr_q, p.override_of());
    one("mcnt_q", r.dda_pace__DOT__mcnt_q, std::uint64_t(p.override_busy()));
    if (!diff.empty()) FAIL("after clock " << clocks_ - 1 << " (rtl/model): " << diff);
    max_phase_ = std::max(max_phase_, p.phase_value());
    corrected_ = corrected_ || p.phase_value() < 0;
    held_ = held_ || (p.speed() == 0 && p.norm_busy() == 0 && !p.pending() && p.to_go() > 0);
  }
  std::uint64_t iterations() const { return iterations_; }
  std::int64_t max_phase() const { return max_phase_; }
  bool corrected() const { return corrected_; }  // a correction took the phase below 0
  bool held() const { return held_; }            // the speed was 0 in the middle of a piece

 private:
  void clock() {
    top_->clk_i = 0;
    top_->eval();
    top_->clk_i = 1;
    top_->eval();
    ++clocks_;
  }
  std::unique_ptr<Vdda_pace> top_;
  std::uint64_t clocks_ = 0, iterations_ = 0;
  std::int64_t max_phase_ = 0;
  bool held_ = false, corrected_ = false;
};

using Each = std::function<void(std::uint64_t, PaceSettings&)>;
struct Seen {
  std::int64_t max_phase = 0;
  bool corrected = false;
  bool held = false;
};
// Runs the plan clock by clock with the RTL beside the model; returns the model's result.
PaceResult lockstep(const Plan& plan, const PaceOptions& o, const Each& each = nullptr, Seen* seen = nullptr) {
  Lockstep rtl;
  PaceHooks h;
  h.clock_by_clock = true;
  h.each = each;
  h.edge = [&](const Pacer& p, const Pacer::In& in) { rtl.edge(p, in); };
  h.watch = [&](std::uint64_t, const Pacer& p, double) { rtl.compare(p); };
  const PaceResult r = pace_plan(plan, o, h);
  CHECK(rtl.iterations() == r.iterations);
  if (seen) *seen = Seen{rtl.max_phase(), rtl.corrected(), rtl.held()};
  return r;
}

// The paper's example: the 10 x 6 ellipse at 4 bits, zero preload, a quarter.
Plan paper() {
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  s.preload = Preload::Zero;
  return plan_arc(s);
}
Plan quarter(std::int64_t a, std::int64_t b, std::int64_t angle = 0) {
  ArcSpec s;
  s.a = a;
  s.b = b;
  s.angle = angle;
  s.preload = Preload::Half;
  return plan_arc(s);
}

}  // namespace

TEST_CASE("pace unit: the RTL decides and holds what the reference model does, arc by arc", "[pacer][rtl]") {
  struct Case {
    const char* name;
    Plan plan;
    PaceOptions o;
  };
  ArcSpec circle;
  circle.a = circle.b = 300;
  circle.preload = Preload::Half;
  const std::vector<Case> cases = {
      {"the paper's example", paper(), {2e4, 1e7, 500, kClock}},
      {"line 900 x 250", plan_line(Point{}, Point{900, 250, 0}, Preload::Half), {4e4, 2e7, 500, kClock}},
      {"circle of radius 300", plan_arc(circle), {4e4, 2e7, 1000, kClock}},
      {"rotated quarter 400 x 100", quarter(400, 100, 30000000), {1.5e4, 1e7, 300, kClock}},
      {"3-D line, no ramp", plan_line(Point{}, Point{300, -200, 150}, Preload::Half), {4e4, 0, 0, kClock}},
      {"a quarter circle of radius 2000 near the stepping rate", quarter(2000, 2000), {1.5e5, 4e7, 2000, kClock}},
      {"an eccentric quarter 400 x 40 at speed", quarter(400, 40, 10000000), {1.2e5, 4e7, 2000, kClock}},
      {"a speed beyond the norm unit's stepping rate",
       plan_line(Point{}, Point{6000, 100, 0}, Preload::Half),
       {3.9e6, 0, 0, kClock}},
  };
  bool corrected = false;
  for (const auto& c : cases) {
    INFO(c.name);
    Seen seen;
    const PaceResult r = lockstep(c.plan, c.o, nullptr, &seen);
    CHECK(r.end == c.plan.to);
    CHECK(r.iterations > 20);
    CHECK_FALSE(seen.held);
    // The phase saturates only when the speed is beyond the core's.
    CHECK((seen.max_phase == std::int64_t(mask(kPhaseBits))) == (c.o.feed > 1e6));
    corrected = corrected || seen.corrected;
  }
  // Some run's provisional iterations were corrected by more than the phase held.
  CHECK(corrected);
}

TEST_CASE("pace unit: holds and overrides in lockstep with the reference model", "[pacer][rtl]") {
  const Plan plan = quarter(600, 400);
  const PaceOptions o{4e4, 2e7, 500, kClock};
  Seen seen;
  const PaceResult held = lockstep(
      plan, o,
      [](std::uint64_t clock, PaceSettings& s) {
        s.hold = (clock >= 20000 && clock < 40000) || (clock >= 50000 && clock < 50400);
      },
      &seen);
  CHECK(held.end == plan.to);
  CHECK(seen.held);
  const PaceResult over = lockstep(plan, o, [](std::uint64_t clock, PaceSettings& s) {
    s.override_ = clock < 10000   ? kOverrideOne
                  : clock < 30000 ? kOverrideOne / 3
                  : clock < 45000 ? 2 * kOverrideOne
                                  : 0;
    if (clock >= 55000) s.override_ = kOverrideOne + 7;
  });
  CHECK(over.end == plan.to);
}

TEST_CASE("pace unit: the decisions exactly at their comparison boundaries, in lockstep with the reference model",
          "[pacer][rtl]") {
  // Fields chosen so that the comparisons meet their thresholds: the cruise speed k ramp
  // steps above the minimum speed, and one unit either side (the last step up with the
  // target exactly a away, the speed equal to the minimum); lone lines of the shortest
  // lengths along an axis (d exactly one step: the distance to go equal to d on the last
  // iteration, the braking distance and the margin against it); and a circle of radius 2,
  // four pieces back to back whose exit speed equals the cruise speed.
  const std::uint64_t a = std::uint64_t{1} << 20;                           // x 2^-kRampFrac steps/clock^2
  const std::uint32_t vmin = 1u << 22;                                      // x 2^-kSpeedFrac steps/clock
  const std::uint32_t step = std::uint32_t(a >> (kRampFrac - kSpeedFrac));  // a in entry speed units
  const auto speed = [](std::uint32_t f) { return std::ldexp(double(f), -kSpeedFrac) * kClock; };
  ArcSpec tiny;
  tiny.a = tiny.b = 2;
  tiny.preload = Preload::Half;
  tiny.from = tiny.to = Point{2, 0, 0};
  std::vector<std::pair<std::string, Plan>> plans;
  for (std::int64_t len = 1; len <= 3; ++len)
    plans.emplace_back("a line of " + std::to_string(len), plan_line(Point{}, Point{len, 0, 0}, Preload::Half));
  plans.emplace_back("a circle of radius 2", plan_arc(tiny));
  int runs = 0;
  for (std::uint32_t k = 0; k <= 3; ++k) {
    for (int off = -1; off <= 1; ++off) {
      if (k == 0 && off < 0) continue;  // (the cruise speed below the minimum)
      const std::uint32_t cruise = vmin + k * step + std::uint32_t(off);
      const PaceOptions o{speed(cruise), std::ldexp(double(a), -kRampFrac) * kClock * kClock, speed(vmin), kClock};
      REQUIRE(speed_field(o.feed, kClock) == cruise);
      REQUIRE(accel_field(o.accel, kClock) == a);
      for (const auto& [name, plan] : plans) {
        INFO(name << ", cruise " << cruise << " (" << k << " ramp steps above the minimum speed, " << off << ")");
        const PaceResult r = lockstep(plan, o);
        CHECK(r.end == plan.to);
        ++runs;
      }
    }
  }
  CHECK(runs == 44);
}

TEST_CASE("pace unit: the bus vector sets at the thresholds carry the fields they are named for", "[pacer]") {
  // tests/rtl_checks.cmake's pace_step and pace_step_less: on a clock of 2^20 Hz, 65536
  // steps/s^2 is a ramp step of 256 entry speed units, 1000 steps/s a whole field.
  const double clock = 1048576;
  const std::uint32_t vmin = speed_field(1000, clock);
  const std::uint32_t step = std::uint32_t(accel_field(65536, clock) >> (kRampFrac - kSpeedFrac));
  CHECK(step == 256);
  CHECK(speed_field(1000.0625, clock) == vmin + step);
  CHECK(speed_field(1000.124755859375, clock) == vmin + 2 * step - 1);
}

namespace {

// The pacer's decision to slow down compares s + the phase + the margin with the
// distance to go (+ the exit's braking distance): the left side less the right, plus
// the distance the iterations have taken off (which the phase loses as much of), on the
// clock before edge `clock` of a lone entry of `length`, driven by hand (a core whose
// every iteration moves one step, never stepping: one run), as the reference sees it.
struct Drive {
  Pacer::In in;
  Drive(std::uint64_t accel, std::uint32_t vmin, std::uint32_t cruise, std::uint32_t length) {
    in.advance = in.running = true;
    in.set.accel = accel;
    in.set.vmin = vmin;
    in.norm = NormOperands{1u << 20, 0, 0, 1u << 20, 1u << 20};  // d: one step
    in.entry = PaceEntry{cruise, cruise, 0, length, 0};
  }
};

}  // namespace

TEST_CASE("pace unit: the braking decision on the very clock its two sides are equal, RTL and reference",
          "[pacer][rtl]") {
  // The comparison meets equality only when both sides agree to 2^-32 step, which
  // planned pieces reach by chance alone. Built here: a ramp of 2^31 per clock to the
  // minimum speed, a whole number of steps of it (so no braking distance is counted on
  // the way up), and a cruise speed within a step above it, with every speed a multiple
  // of 2^16 at the phase's scale; the phase as a distance then comes back to every
  // residue modulo one length unit (2^24 at kDistFrac) within 512 clocks. A first run
  // with a long entry finds a clock at cruise where the left side, with the distance
  // gone, is a whole number of length units; the entry of exactly that length then meets
  // equality on that clock, and the pacer heads for the minimum speed from it.
  const std::uint64_t a = std::uint64_t{1} << 31;
  const std::uint32_t vmin = std::uint32_t((std::uint64_t{40} * a) >> (kRampFrac - kSpeedFrac));
  const std::uint32_t cruise = vmin + (1u << 13);
  const std::int64_t margin = std::int64_t{1} << (kDistFrac - kMarginShift);
  const std::int64_t unit = std::int64_t{1} << (kDistFrac - kLenFrac);
  // The left side with the distance gone, clock by clock, on a long entry.
  std::optional<std::pair<int, std::int64_t>> hit;
  {
    Drive dr(a, vmin, cruise, 1u << 30);
    Pacer p;
    dr.in.take = true;
    p.edge(dr.in);
    dr.in.take = false;
    const std::int64_t length = std::int64_t(std::uint64_t{1} << 30) * unit;
    for (int c = 1; c < 4000 && !hit; ++c) {
      const std::int64_t left = std::int64_t(p.brake()) + (p.phase_value() >> (kRampFrac - kDistFrac)) + margin;
      const std::int64_t gone = length - std::int64_t(p.to_go());
      if (c > 2 * kOverrideClocks && p.speed() == p.cruise_speed() && (left + gone) % unit == 0)
        hit = std::make_pair(c, (left + gone) / unit);
      p.edge(dr.in);
    }
  }
  REQUIRE(hit);
  INFO("equal on clock " << hit->first << " of an entry of " << hit->second << " length units");
  Lockstep rtl;
  Pacer p;
  Drive dr(a, vmin, cruise, std::uint32_t(hit->second));
  dr.in.take = true;
  rtl.edge(p, dr.in);
  p.edge(dr.in);
  rtl.compare(p);
  dr.in.take = false;
  bool equal = false;
  std::uint64_t before = 0;
  for (int c = 1; c < 4000; ++c) {
    const std::int64_t left = std::int64_t(p.brake()) + (p.phase_value() >> (kRampFrac - kDistFrac)) + margin;
    if (c == hit->first) {
      equal = left == std::int64_t(p.to_go());
      before = p.speed();
      CHECK(p.target(dr.in) == std::uint64_t(vmin) << (kRampFrac - kSpeedFrac));  // slowing down from here
    }
    rtl.edge(p, dr.in);
    p.edge(dr.in);
    rtl.compare(p);
    if (c == hit->first) CHECK(p.speed() < before);
  }
  CHECK(equal);
}
