// SPDX-License-Identifier: Apache-2.0
// The runner: a plan's pieces through the golden datapath, with the run-time guards.
#include "dda/runner.hpp"

#include <sstream>
#include <string>
#include <tuple>

namespace dda {

namespace {

std::string pt(Point p) {
  std::ostringstream s;
  s << '(' << p.x << ',' << p.y << ')';
  return s.str();
}

// Runs piece k; iteration numbers continue from first_iter.
RunSummary run_piece(const Plan& plan, std::size_t k, std::uint64_t first_iter,
                     const std::function<void(const Iteration&)>* on_iter, bool for_validation) {
  const Piece& pc = plan.pieces[k];
  Datapath dp(pc.cmd, pc.from);
  while (!dp.done()) {
    // An active axis' integrand must stay within [-cap, cap]: above cap an accumulator
    // could carry twice in one iteration. The planner refuses such an arc.
    const auto& rg = dp.regs();
    for (const auto& [axis, active, jv] :
         {std::tuple{'X', rg.cnt_x != 0, rg.jv_x}, std::tuple{'Y', rg.cnt_y != 0, rg.jv_y}}) {
      if (active && (jv < -pc.cmd.cap || jv > pc.cmd.cap)) {
        std::ostringstream m;
        m << "end point " << pt(plan.to) << " is unreachable from " << pt(plan.from) << ": at " << pt(dp.pos())
          << " the " << axis << " integrand's magnitude exceeds the capacity with "
          << (axis == 'X' ? rg.cnt_x : rg.cnt_y) << ' ' << axis << " step(s) still owed";
        if (for_validation) throw InputError(m.str());
        throw GuardError("integrand guard: " + m.str());
      }
    }
    if (dp.stalled()) {
      const auto& r = dp.regs();
      const char axis = (r.cnt_y != 0 && r.jv_y == 0) ? 'Y' : 'X';
      const std::int64_t owed = axis == 'Y' ? r.cnt_y : r.cnt_x;
      std::ostringstream m;
      m << "end point " << pt(plan.to) << " is unreachable from " << pt(plan.from) << ": at " << pt(dp.pos()) << " the "
        << axis << " integrand is 0 with " << owed << ' ' << axis << " step(s) still owed (the DDA would never finish)";
      if (for_validation) throw InputError(m.str());
      throw GuardError("stall guard: " + m.str());
    }
    if (dp.iterations() >= pc.iteration_bound) {
      // While planning, a piece that passes its bound does not reach its end: the input's
      // fault (the planner then tries another way, or refuses it); while running, a guard.
      std::ostringstream m;
      m << "the piece to " << pt(pc.to) << " reached its bound of " << pc.iteration_bound << " iterations";
      if (for_validation)
        throw InputError("end point " + pt(plan.to) + " is unreachable from " + pt(plan.from) + ": " + m.str());
      throw GuardError("iteration guard: " + m.str());
    }
    if (!on_iter || !*on_iter) {
      dp.step();
      continue;
    }
    Iteration it = dp.iterate();
    // Back to back, the edge of a piece's last iteration also loads the next piece's
    // command: the registers after it are that command's.
    it.piece_end = dp.done();
    if (it.piece_end && k + 1 < plan.pieces.size()) it.after = initial_regs(plan.pieces[k + 1].cmd);
    it.iter += first_iter;
    it.piece = static_cast<std::uint32_t>(k);
    it.dir_x_neg = pc.cmd.dir_x_neg;
    it.dir_y_neg = pc.cmd.dir_y_neg;
    (*on_iter)(it);
  }
  if (dp.pos() != pc.to) {
    throw GuardError("end-point guard: the counters reached 0 at " + pt(dp.pos()) + " instead of " + pt(pc.to));
  }
  return RunSummary{dp.iterations(), dp.pos(), dp.regs()};
}

RunSummary run_impl(const Plan& plan, const std::function<void(const Iteration&)>* on_iter, bool for_validation) {
  RunSummary total;
  for (std::size_t k = 0; k < plan.pieces.size(); ++k) {
    const RunSummary r = run_piece(plan, k, total.iterations, on_iter, for_validation);
    total.iterations += r.iterations;
    total.end = r.end;
    total.final_regs = r.final_regs;
  }
  return total;
}

}  // namespace

RunSummary run(const Plan& plan, const std::function<void(const Iteration&)>& on_iter) {
  return run_impl(plan, &on_iter, false);
}

std::vector<Iteration> run_records(const Plan& plan) {
  std::vector<Iteration> v;
  run(plan, [&](const Iteration& it) { v.push_back(it); });
  return v;
}

void check_reachable(const Plan& plan) { run_impl(plan, nullptr, /*for_validation=*/true); }

}  // namespace dda
