// SPDX-License-Identifier: Apache-2.0
// The cycle-level reference model (model/datapath/core_model.hpp) against the golden runner: fed a
// plan's commands back to back, it makes the runner's iterations, and its control
// follows docs/design.md (load on the finishing edge, idle after the last piece).
#include <catch2/catch.hpp>

#include "model/datapath/core_model.hpp"
#include "model/datapath/hw_command.hpp"
#include "tb/random/dda_random.hpp"

using namespace dda;

namespace {

// Runs a plan through the model with ce_i from `ce`; returns its iteration records.
template <typename Ce>
std::vector<Iteration> model_records(const Plan& plan, Ce ce, std::uint64_t& cycles) {
  CoreModel m;
  CoreInputs in;
  in.rst_n = false;
  m.edge(in);
  in.rst_n = true;
  std::vector<Iteration> recs;
  std::size_t next = 0, running = 0;
  Point pos = plan.from;
  cycles = 0;
  for (;;) {
    in.ce = ce(cycles);
    in.cmd_valid = next < plan.pieces.size();
    if (in.cmd_valid) in.cmd = hw::command_fields(plan.pieces[next].cmd);
    const Signals pre = m.state();
    const CoreEdge e = m.edge(in);
    ++cycles;
    REQUIRE_FALSE(e.stalled);
    if (e.iterate) {
      Iteration it = CoreModel::iteration_record(pre, m.state());
      pos = pos + CoreModel::step_of(m.state());
      it.iter = recs.size() + 1;
      it.piece = std::uint32_t(running);
      it.pos = pos;
      recs.push_back(it);
    }
    if (e.finishing && ++running == plan.pieces.size()) break;
    if (e.load) ++next;
    REQUIRE(cycles < 100 * (plan.iteration_bound + 10));
  }
  CHECK_FALSE(CoreModel::busy(m.state()));
  return recs;
}

bool same(const Iteration& a, const Iteration& b) {
  return a.iter == b.iter && a.piece == b.piece && a.active_x == b.active_x && a.active_y == b.active_y &&
         a.jv_x == b.jv_x && a.jv_y == b.jv_y && a.sum_x == b.sum_x && a.sum_y == b.sum_y && a.step_x == b.step_x &&
         a.step_y == b.step_y && a.after == b.after && a.pos == b.pos && a.dir_x_neg == b.dir_x_neg &&
         a.dir_y_neg == b.dir_y_neg && a.active_z == b.active_z && a.jv_z == b.jv_z && a.sum_z == b.sum_z &&
         a.step_z == b.step_z && a.dir_z_neg == b.dir_z_neg;
}

}  // namespace

TEST_CASE("core model: 200 random arcs make the golden runner's iterations, back to back", "[core_model]") {
  const std::uint64_t seed = test_seed(41);
  RandomArcs quarter(seed, 4096, 8), whole(seed + 1, 4096, 8, ArcKind::Whole);
  RandomArcs spatial(seed + 2, 1024, 8, ArcKind::Spatial);  // lines, plunges, helices
  for (int n = 0; n < 200;) {
    const auto plan = (n % 3 == 2 ? spatial : n % 2 ? whole : quarter).next();
    if (!plan) continue;
    ++n;
    INFO("seed " << seed << ": dda trace " << describe(*plan));
    std::uint64_t cycles = 0;
    const auto got = model_records(
        *plan, [](std::uint64_t) { return true; }, cycles);
    const auto want = run_records(*plan);
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      INFO("iteration " << i + 1);
      // The runner's record after a piece's last iteration holds the next piece's loaded
      // registers; so does the model's, which loads on that edge.
      REQUIRE(same(got[i], want[i]));
    }
    std::size_t empty = 0;  // a command without a step finishes on an edge of its own
    for (const auto& pc : plan->pieces) empty += pc.cmd.cnt_x == 0 && pc.cmd.cnt_y == 0 && pc.cmd.cnt_z == 0;
    CHECK(cycles == want.size() + 1 + empty);  // one load edge, then one iteration per edge
  }
}

TEST_CASE("core model: ce_i low holds every register but the pulses", "[core_model]") {
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  const Plan plan = plan_arc(s);
  std::uint64_t cycles = 0;
  const auto slow = model_records(
      plan, [](std::uint64_t c) { return c % 3 != 1; }, cycles);
  const auto want = run_records(plan);
  REQUIRE(slow.size() == want.size());
  for (std::size_t i = 0; i < slow.size(); ++i) CHECK(same(slow[i], want[i]));
  CHECK(cycles > want.size() + 1);
}
