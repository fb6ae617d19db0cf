// SPDX-License-Identifier: Apache-2.0
// Property tests over random configurations of the golden model.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "host/accuracy/golden.hpp"
#include "tb/random/dda_random.hpp"

using namespace dda;

namespace {

// Checks every documented invariant of one run; returns the first violation or "".
// The deviation bound is checked only where its start-offset term is at most one step
// (elsewhere it is too loose to mean much; the callers count how often that happens).
std::string check_run(const Plan& plan) {
  std::ostringstream err;
  Point prev = plan.from;
  const double bound = deviation_bound(plan);
  const bool check_dev = start_offset(plan) <= 1.0 && std::isfinite(bound);
  const auto dev = [&](Point p) { return plan_distance(plan, double(p.x), double(p.y)); };
  if (check_dev && dev(plan.from) > bound) err << "start point deviates " << dev(plan.from);
  try {
    const RunSummary s = run(plan, [&](const Iteration& it) {
      if (!err.str().empty()) return;
      const auto& r = it.after;
      // After a piece's last iteration the registers are the next piece's loaded ones.
      const bool next = it.piece_end && it.piece + 1 < plan.pieces.size();
      const std::int64_t cap = plan.pieces[it.piece + (next ? 1 : 0)].cmd.cap;
      if (r.jr_x < 0 || r.jr_x >= cap || r.jr_y < 0 || r.jr_y >= cap) {
        err << "iteration " << it.iter << ": accumulator outside [0, cap) after overflow removal";
      }
      if (std::llabs(it.pos.x - prev.x) > 1 || std::llabs(it.pos.y - prev.y) > 1) {
        err << "iteration " << it.iter << ": moved more than one step on an axis";
      }
      if (check_dev && (it.step_x || it.step_y)) {
        const double d = dev(it.pos);
        if (d > bound) {
          err << "iteration " << it.iter << ": point (" << it.pos.x << ',' << it.pos.y << ") deviates " << d
              << " > bound " << bound;
        }
      }
      prev = it.pos;
    });
    if (err.str().empty() && s.end != plan.to) err << "did not end at the end point";
  } catch (const GuardError& e) {
    err << "guard: " << e.what();
  }
  return err.str();
}

}  // namespace

TEST_CASE("properties: 10,000 random configurations hold every invariant", "[golden][random]") {
  const std::uint64_t seed = test_seed(20261122);
  RandomArcs gen(seed, 4096);
  int checked = 0, non_default = 0, dev_checked = 0;
  while (checked < 10000) {
    const auto drawn = gen.next();
    if (!drawn) continue;
    const Plan& plan = *drawn;
    non_default += !(plan.from == Point{plan.arc().spec.a, 0} && plan.to == Point{0, plan.arc().spec.b});
    dev_checked += start_offset(plan) <= 1.0;
    const std::string err = check_run(plan);
    if (!err.empty()) {
      FAIL("seed " << seed << ", case " << checked << ": " << describe(plan) << ": " << err);
    }
    ++checked;
  }
  INFO("seed " << seed << ", rejected draws " << gen.rejected());
  CHECK(non_default > 5000);
  CHECK(dev_checked > 5000);  // the deviation bound was checked on more than half of the runs
  CHECK(gen.rejected() < 2000);
}

TEST_CASE("properties: 3,000 random whole-ellipse arcs hold every invariant", "[golden][random]") {
  const std::uint64_t seed = test_seed(20261123);
  RandomArcs gen(seed, 4096, 8, ArcKind::Whole);
  int checked = 0, multi = 0, full = 0, dev_checked = 0, rotated = 0, rotated_dev = 0;
  while (checked < 3000) {
    const auto drawn = gen.next();
    if (!drawn) continue;
    const bool dev = start_offset(*drawn) <= 1.0 && std::isfinite(deviation_bound(*drawn));
    dev_checked += dev;
    rotated += drawn->arc().rotated;
    rotated_dev += drawn->arc().rotated && dev;
    const std::string err = check_run(*drawn);
    if (!err.empty()) FAIL("seed " << seed << ", case " << checked << ": " << describe(*drawn) << ": " << err);
    multi += drawn->pieces.size() > 1;
    full += drawn->arc().full;
    ++checked;
  }
  INFO("seed " << seed << ", rejected draws " << gen.rejected());
  CHECK(multi > 1500);
  CHECK(full > 200);
  CHECK(dev_checked > 1000);  // the deviation bound was checked on a third or more
  CHECK(rotated > 1000);      // half the draws are turned by a uniform angle
  CHECK(rotated_dev > 50);    // half preload, default width or more, aspect <= 4
  CHECK(gen.rejected() < 100);
}

TEST_CASE("properties: a wrong variant (integrands not corrected) breaks them", "[golden][random]") {
  // Built only here: the command of a correct plan with one integrand correction
  // removed, as if the hardware forgot to update JVY after an X step. Arcs of at least
  // 16 steps on each axis, where a lost correction has room to show.
  const std::uint64_t seed = test_seed(7);
  RandomArcs gen(seed, 4096);
  int broken = 0, tried = 0;
  while (tried < 200) {
    auto drawn = gen.next();
    if (!drawn || drawn->cmd().cnt_x < 16 || drawn->cmd().cnt_y < 16) continue;
    Plan plan = *drawn;
    REQUIRE(check_run(plan).empty());
    for (auto& sg : plan.pieces) sg.cmd.inc_y_on_x = 0;
    ++tried;
    broken += !check_run(plan).empty();
  }
  INFO("seed " << seed << ": " << broken << " of " << tried << " broken runs caught");
  CHECK(broken >= 100);
  // The paper's example with no integrand corrected at all: X never starts (stall).
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  Plan paper = plan_arc(s);
  paper.pieces[0].cmd.inc_y_on_x = 0;
  paper.pieces[0].cmd.inc_x_on_y = 0;
  CHECK_FALSE(check_run(paper).empty());
}

TEST_CASE("properties: iteration bound is not passed by the worst-case shapes", "[golden]") {
  for (std::int64_t a : {1, 2, 3, 4095, 4096}) {
    for (std::int64_t b : {1, 2, 3, 4095, 4096}) {
      const int n0 = smallest_valid_bits(a, b);
      for (int n : {n0, n0 + 8}) {
        for (Preload p : {Preload::Zero, Preload::Half}) {
          ArcSpec s;
          s.a = a;
          s.b = b;
          s.bits = n;
          s.preload = p;
          const Plan plan = plan_arc(s);
          INFO(describe(plan));
          CHECK(check_run(plan).empty());
        }
      }
    }
  }
}

namespace {

// Every iteration of a command through next_state(), against the closed-form skip of the
// iterations without a step (Datapath::skip_quiet): the same registers and the same
// iteration number at every step, up to `limit` iterations. "" when they agree.
std::string compare_skip(const Command& cmd, std::uint64_t limit) {
  RegState slow = initial_regs(cmd), fast = slow;
  std::uint64_t slow_it = 0, fast_it = 0;
  while (slow_it < limit) {
    const StepOut o = next_state(cmd, slow);
    ++slow_it;
    if (!o.step_x && !o.step_y && !o.step_z) continue;
    const std::uint64_t q = quiet_iterations(cmd, fast);
    if (q == kNever) return "the skip found no step at iteration " + std::to_string(slow_it);
    skip_quiet(cmd, fast, q);
    const StepOut f = next_state(cmd, fast);
    fast_it += q + 1;
    if (fast_it != slow_it || !(fast == slow) || f.step_x != o.step_x || f.step_y != o.step_y || f.step_z != o.step_z) {
      return "the skip's step is at iteration " + std::to_string(fast_it) + ", next_state's at " +
             std::to_string(slow_it);
    }
    if (finished(slow)) return "";
  }
  // No step in the rest: the skip must not find one before the limit either.
  const std::uint64_t q = quiet_iterations(cmd, fast);
  if (q != kNever && fast_it + q + 1 <= limit) return "the skip finds a step next_state does not";
  return "";
}

}  // namespace

TEST_CASE("properties: skipping the iterations without a step equals iterating", "[golden][random]") {
  const std::uint64_t seed = test_seed(20261201);
  // The planner's commands: every piece of random arcs and lines as programs give them.
  RandomArcs gen(seed, 2048, 6, ArcKind::Program);
  int pieces = 0;
  for (int k = 0; k < 400; ++k) {
    const auto drawn = gen.next();
    if (!drawn) continue;
    for (const Piece& pc : drawn->pieces) {
      const std::string err = compare_skip(pc.cmd, pc.iteration_bound);
      if (!err.empty()) FAIL("seed " << seed << ": " << describe(*drawn) << ", piece " << pieces << ": " << err);
      ++pieces;
    }
  }
  CHECK(pieces > 400);
  // Commands no planner writes: negative and zero integrands, preloads at or above the
  // capacity, corrections of either sign, counters that stop one axis early, a third
  // axis beside them.
  std::mt19937_64 rng(seed);
  const auto in = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  for (int k = 0; k < 20000; ++k) {
    Command c;
    c.cap = in(1, 1 << 12);
    c.jv_x = in(-c.cap / 4, c.cap);
    c.jv_y = in(-c.cap / 4, c.cap);
    c.jr_x = in(0, c.cap + c.cap / 8);
    c.jr_y = in(0, c.cap + c.cap / 8);
    c.cnt_x = in(0, 40);
    c.cnt_y = in(0, 40);
    c.inc_x_on_x = in(-3, 3), c.inc_x_on_y = in(-40, 40);
    c.inc_y_on_x = in(-40, 40), c.inc_y_on_y = in(-3, 3);
    if (k % 2 != 0) {  // the third axis, zero integrands and high preloads included
      c.cap_z = in(1, 1 << 12);
      c.jv_z = in(0, c.cap_z);
      c.jr_z = in(0, c.cap_z + c.cap_z / 8);
      c.cnt_z = in(0, 40);
    }
    const std::string err = compare_skip(c, 200000);
    if (!err.empty()) FAIL("seed " << seed << ", command " << k << ": " << err);
  }
}
