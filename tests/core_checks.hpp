// SPDX-License-Identifier: Apache-2.0
// Checks shared by the SystemC-model and RTL test programs: the same stimulus and the
// same expectations (all from the golden model) for every engine.
#pragma once

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "host/report/report.hpp"
#include "model/datapath/hw_command.hpp"
#include "tb/engines/core_driver.hpp"
#include "tb/random/dda_random.hpp"

namespace dda::checks {

// A signal of a sample by its name in the register table.
inline std::uint64_t reg(const Signals& s, std::string_view name) { return s[hw::sig(name)]; }

inline Plan paper_plan(Preload p = Preload::Zero) {
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  s.preload = p;
  return plan_arc(s);
}

inline bool same(const Iteration& a, const Iteration& b) {
  return a.iter == b.iter && a.active_x == b.active_x && a.active_y == b.active_y && a.jv_x == b.jv_x &&
         a.jv_y == b.jv_y && a.sum_x == b.sum_x && a.sum_y == b.sum_y && a.step_x == b.step_x && a.step_y == b.step_y &&
         a.after == b.after && a.pos == b.pos;
}

// Commands with every count zero: the core finishes each on an edge without an iteration.
inline std::uint64_t empty_pieces(const dda::Plan& p) {
  std::uint64_t n = 0;
  for (const auto& pc : p.pieces) n += pc.cmd.cnt_x == 0 && pc.cmd.cnt_y == 0 && pc.cmd.cnt_z == 0;
  return n;
}

inline void records_equal(const std::vector<Iteration>& got, const std::vector<Iteration>& want) {
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("iteration " << i + 1);
    CHECK(same(got[i], want[i]));
  }
}

inline std::string trace_csv(const Plan& plan, const std::vector<Iteration>& recs) {
  std::ostringstream os;
  write_trace(os, plan, recs, TraceFormat::Csv);
  return os.str();
}

inline std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// The paper's example: every register after every iteration equals the golden record.
inline void paper_example(CoreHarness& h) {
  reset_core(h);
  const Plan plan = paper_plan();
  const auto got = drive_arc(h, plan).records;  // the scoreboard checks each iteration
  records_equal(got, run_records(plan));
  CHECK(trace_csv(plan, got) == trace_csv(plan, run_records(plan)));
}

// The paper's example on a harness of type H writing a waveform: the run checks out and
// the waveform holds the architectural registers and the whole run.
template <typename H>
void paper_example_with_waveform(const std::string& tag) {
  const auto vcd =
      std::filesystem::temp_directory_path() / ("dda_test_" + tag + "_" + std::to_string(::getpid()) + ".vcd");
  std::filesystem::remove(vcd);
  {
    H h(vcd.string());
    paper_example(h);
    h.close_trace();
  }
  const std::string v = slurp(vcd.string());
  for (const char* scope : {"u_int_x", "u_int_y", "u_cnt_x", "u_cnt_y", "u_ctrl"}) {
    CHECK(v.find(std::string("$scope module ") + scope + " $end") != std::string::npos);
  }
  for (const char* reg : {" jv_q ", " jr_q ", " cnt_q ", " state_q ", " step_x_q ", " cap_q "}) {
    CHECK(v.find(reg) != std::string::npos);
  }
  CHECK(v.find("\n#300\n") != std::string::npos);  // 30 cycles of 10 ns
  std::filesystem::remove(vcd);
}

// Runs a plan on a (deliberately broken) core; returns the mismatch message, or "".
// The harness stops checking after it (its reference model has seen a different run).
inline std::string mismatch_message(CoreHarness& h, const Plan& plan) {
  reset_core(h);
  std::string message;
  try {
    drive_arc(h, plan);
  } catch (const MismatchError& e) {
    message = e.what();
  }
  h.disable_checking();
  return message;
}

// Random arcs back to back, each in lockstep with the golden model.
inline void random_arcs(CoreHarness& h, std::uint64_t seed, int count, ArcKind kind = ArcKind::Quarter) {
  RandomArcs gen(seed, 4096, 8, kind);
  reset_core(h);
  for (int arcs = 0; arcs < count;) {
    const auto plan = gen.next();
    if (!plan) continue;
    INFO("seed " << seed << ", arc " << arcs << ": dda trace " << describe(*plan));
    DriveOptions opt;
    opt.keep_records = false;
    const DriveResult r = drive_arc(h, *plan, opt);
    REQUIRE(r.end == plan->to);
    REQUIRE(r.iterations == run(*plan).iterations);
    // Pieces back to back: one edge to load the first command, then one iteration on
    // every edge to the end (no idle cycle between pieces); a command without a step (an
    // arc shorter than a step) takes one edge to finish.
    REQUIRE(r.cycles == r.iterations + 1 + empty_pieces(*plan));
    ++arcs;
  }
}

// A random ce_i pattern (long stalls included) gives the same records, stretched.
inline void ce_stretch(CoreHarness& h, std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  RandomArcs gen(seed, 512);
  reset_core(h);
  for (int arcs = 0; arcs < count;) {
    const auto plan = gen.next();
    if (!plan) continue;
    ++arcs;
    INFO("seed " << seed << ": dda trace " << describe(*plan));
    const DriveResult ref = drive_arc(h, *plan);
    DriveOptions opt;
    std::uint64_t until = 0;
    bool level = true;
    opt.ce = [&](std::uint64_t c) {
      if (c >= until) {
        level = !level;
        until = c + (level ? 1 + rng() % 10 : (rng() % 16 == 0 ? 300 : 1 + rng() % 40));
      }
      return level;
    };
    const DriveResult slow = drive_arc(h, *plan, opt);
    records_equal(slow.records, ref.records);
    CHECK(slow.cycles > ref.cycles);
  }
}

// Reset in the middle of an arc: idle, no pulse after it; the next command runs.
inline void reset_midway(CoreHarness& h) {
  reset_core(h);
  DriveOptions cut;
  cut.reset_after = 12;
  CHECK(drive_arc(h, paper_plan(Preload::Half), cut).iterations == 12);
  h.set_ce(true);
  for (int i = 0; i < 50; ++i) {
    h.tick();
    const Signals s = h.sample();
    CHECK(reg(s, "u_ctrl.state_q") == unsigned(hw::State::Idle));
    CHECK_FALSE(reg(s, "step_x_q"));
    CHECK_FALSE(reg(s, "step_y_q"));
    CHECK_FALSE(reg(s, "u_ctrl.iter_q"));
    CHECK_FALSE(reg(s, "u_ctrl.done_q"));
    CHECK(reg(s, "u_cnt_x.cnt_q") == 0);
    CHECK(reg(s, "u_cnt_y.cnt_q") == 0);
    CHECK(h.cmd_ready());
  }
  const Plan next = paper_plan();
  records_equal(drive_arc(h, next).records, run_records(next));
}

// Hands a raw command over and clocks one edge with ce_i high; returns the sample after.
inline Signals load_and_clock(CoreHarness& h, const Command& c) {
  h.set_command(true, hw::command_fields(c));
  h.set_ce(false);
  REQUIRE(h.cmd_ready());
  h.tick();
  h.set_command(false);
  h.set_ce(true);
  h.tick();
  return h.sample();
}

// The control paths the driver never uses: a command with nothing to do finishes
// without an iteration; a command that can never carry raises err_o and returns to
// idle, and the core then runs the next command normally.
inline void finished_and_stalled(CoreHarness& h) {
  reset_core(h);
  Command empty = paper_plan().cmd();
  empty.cnt_x = empty.cnt_y = 0;
  REQUIRE(Datapath(empty, Point{}).done());
  Signals s = load_and_clock(h, empty);
  CHECK(reg(s, "u_ctrl.done_q"));
  CHECK_FALSE(reg(s, "u_ctrl.iter_q"));
  CHECK_FALSE(reg(s, "u_ctrl.err_q"));
  CHECK(reg(s, "u_ctrl.state_q") == unsigned(hw::State::Idle));

  Command stuck = paper_plan().cmd();  // X owes 10 steps, Y none: the X integrand stays 0
  stuck.cnt_y = 0;
  REQUIRE(Datapath(stuck, Point{}).stalled());
  s = load_and_clock(h, stuck);
  CHECK(reg(s, "u_ctrl.err_q"));
  CHECK_FALSE(reg(s, "u_ctrl.iter_q"));
  CHECK_FALSE(reg(s, "u_ctrl.done_q"));
  CHECK(reg(s, "u_ctrl.state_q") == unsigned(hw::State::Idle));
  CHECK(reg(s, "u_int_x.jr_q") == std::uint64_t(stuck.jr_x));  // no iteration happened
  h.tick();
  CHECK_FALSE(reg(h.sample(), "u_ctrl.err_q"));  // one-cycle pulse

  Command neg = stuck;  // a negative integrand cannot carry either
  neg.jv_x = -5;
  REQUIRE(Datapath(neg, Point{}).stalled());
  s = load_and_clock(h, neg);
  CHECK(reg(s, "u_ctrl.err_q"));
  CHECK_FALSE(reg(s, "u_ctrl.iter_q"));
  h.tick();

  const Plan next = paper_plan();
  records_equal(drive_arc(h, next).records, run_records(next));
}

// A negative integrand holds its axis (no add, no carry) until the other axis' steps
// make it positive: the rotated pieces rely on it at a step's overshoot.
inline void negative_integrand_holds(CoreHarness& h) {
  reset_core(h);
  Plan held = paper_plan();
  Command& c = held.pieces.front().cmd;
  c = Command{};
  c.cap = 1000;
  c.jv_x = -500;       // X starts negative ...
  c.inc_x_on_y = 240;  // ... and each Y step raises it
  c.jv_y = 300;
  c.jr_x = c.jr_y = 500;
  c.cnt_x = 2;
  c.cnt_y = 6;
  Datapath dp(c, held.from);
  bool held_seen = false;
  while (!dp.done()) {
    REQUIRE(dp.iterations() < 1000);
    held_seen = held_seen || dp.regs().jv_x < 0;
    dp.step();
  }
  REQUIRE(held_seen);
  held.pieces.resize(1);
  held.pieces.front().to = held.to = dp.pos();
  held.pieces.front().iteration_bound = held.iteration_bound = 1000;
  const auto golden = run_records(held);
  CHECK(golden.front().sum_x == c.jr_x);  // held: the accumulator did not add
  records_equal(drive_arc(h, held).records, golden);
}

}  // namespace dda::checks
