// SPDX-License-Identifier: Apache-2.0
// The runner: a plan's pieces through the golden datapath, with the run-time guards.
#include "host/runner/runner.hpp"

#include <sstream>
#include <string>
#include <tuple>

namespace dda {

namespace {

std::string pt(Point p) {
  std::ostringstream s;
  s << '(' << p.x << ',' << p.y;
  if (p.z != 0) s << ',' << p.z;  // (a point of a run that never moves the third axis: two coordinates)
  s << ')';
  return s.str();
}

// What a piece's run reports on: its place in the stream, the ends named in messages,
// and the command loaded by its last iteration (none for the last piece).
struct PieceRun {
  const Piece& pc;
  std::uint32_t index;
  std::uint64_t first_iter;
  Point from, to;  // the path's ends (the plan's, or the piece's in a stream)
  const Command* next;
};

// The guards before an iteration: an active axis' integrand must stay within
// [-cap, cap] (above cap an accumulator could carry twice in one iteration; the planner
// refuses such an arc), the path must not stall, and the piece must not pass its bound.
inline bool guards_hold(const PieceRun& r, const Datapath& dp) {
  const auto& rg = dp.regs();
  const std::int64_t cap = r.pc.cmd.cap;
  const bool wide_x = rg.cnt_x != 0 && (rg.jv_x < -cap || rg.jv_x > cap);
  const bool wide_y = rg.cnt_y != 0 && (rg.jv_y < -cap || rg.jv_y > cap);
  return !(wide_x || wide_y || dp.stalled() || dp.iterations() >= r.pc.iteration_bound);
}

// A guard that does not hold, in the order guards_hold() reads them, worded twice: for
// a run (a GuardError: the hardware's or the planner's fault) and for the planner's
// reachability check (a Refusal: the input's fault, naming the ends).
struct Tripped {
  std::string guard;     // "stall guard", ...
  std::string detail;    // what a run reports after the guard's name
  std::string as_input;  // what the planner reports
};

Tripped tripped(const PieceRun& r, const Datapath& dp) {
  const Piece& pc = r.pc;
  const auto& rg = dp.regs();
  const std::string ends = "end point " + pt(r.to) + " is unreachable from " + pt(r.from);
  for (const auto& [axis, active, jv] :
       {std::tuple{'X', rg.cnt_x != 0, rg.jv_x}, std::tuple{'Y', rg.cnt_y != 0, rg.jv_y}}) {
    if (active && (jv < -pc.cmd.cap || jv > pc.cmd.cap)) {
      std::ostringstream m;
      m << ends << ": at " << pt(dp.pos()) << " the " << axis << " integrand's magnitude exceeds the capacity with "
        << (axis == 'X' ? rg.cnt_x : rg.cnt_y) << ' ' << axis << " step(s) still owed";
      return Tripped{"integrand guard", m.str(), m.str()};
    }
  }
  if (dp.stalled()) {
    const char axis = (rg.cnt_y != 0 && rg.jv_y == 0) ? 'Y' : 'X';
    const std::int64_t owed = axis == 'Y' ? rg.cnt_y : rg.cnt_x;
    std::ostringstream m;
    m << ends << ": at " << pt(dp.pos()) << " the " << axis << " integrand is 0 with " << owed << ' ' << axis
      << " step(s) still owed (the DDA would never finish)";
    return Tripped{"stall guard", m.str(), m.str()};
  }
  // Else the bound. While planning, a piece that passes its bound does not reach its
  // end: the input's fault (the planner then tries another way, or refuses it); while
  // running, a guard.
  std::ostringstream m;
  m << "the piece to " << pt(pc.to) << " reached its bound of " << pc.iteration_bound << " iterations";
  return Tripped{"iteration guard", m.str(), ends + ": " + m.str()};
}

[[noreturn]] void guard_failed(const PieceRun& r, const Datapath& dp) {
  const Tripped t = tripped(r, dp);
  throw GuardError(t.guard + ": " + t.detail);
}

void check_end(const Piece& pc, const Datapath& dp) {
  if (dp.pos() != pc.to) {
    throw GuardError("end-point guard: the counters reached 0 at " + pt(dp.pos()) + " instead of " + pt(pc.to));
  }
}

// How a piece runs: every iteration a record (`every`), or only those with a step (the
// ones without skipped in closed form, Datapath::skip_quiet), with records or without.
struct RunMode {
  const RecordFn* on_iter = nullptr;
  bool every = true;
};

// The guards hold through the iterations without a step (they read the integrands and
// counters, which hold): only the bound can end them, and it is checked again after.
// Skips them and says whether the guards still hold.
bool skip_quiet(const PieceRun& r, Datapath& dp) {
  const std::uint64_t room = r.pc.iteration_bound - dp.iterations();
  return dp.skip_quiet(room) != room || guards_hold(r, dp);
}

RunSummary run_piece(const PieceRun& r, const RunMode& mode) {
  const Piece& pc = r.pc;
  const RecordFn* on_iter = mode.on_iter && *mode.on_iter ? mode.on_iter : nullptr;
  Datapath dp(pc.cmd, pc.from, pc.rot);
  while (!dp.done()) {
    if (!guards_hold(r, dp)) guard_failed(r, dp);
    if ((!on_iter || !mode.every) && !skip_quiet(r, dp)) guard_failed(r, dp);
    if (!on_iter) {
      dp.step();
      continue;
    }
    Iteration it = dp.iterate();
    // Back to back, the edge of a piece's last iteration also loads the next piece's
    // command: the registers after it are that command's.
    it.piece_end = dp.done();
    if (it.piece_end && r.next) it.after = initial_regs(*r.next);
    it.iter += r.first_iter;
    it.piece = r.index;
    it.dir_x_neg = pc.cmd.dir_x_neg;
    it.dir_y_neg = pc.cmd.dir_y_neg;
    it.dir_z_neg = pc.cmd.dir_z_neg;
    (*on_iter)(it);
  }
  check_end(pc, dp);
  return RunSummary{dp.iterations(), dp.pos(), dp.regs()};
}

// The planner's run of a piece: the same guards, a failure the input's.
std::optional<Refusal> reach_piece(const PieceRun& r) {
  Datapath dp(r.pc.cmd, r.pc.from, r.pc.rot);
  while (!dp.done()) {
    if (!guards_hold(r, dp) || !skip_quiet(r, dp)) return Refusal{tripped(r, dp).as_input};
    dp.step();
  }
  check_end(r.pc, dp);
  return std::nullopt;
}

void add(RunSummary& total, const RunSummary& r) {
  total.iterations += r.iterations;
  total.end = r.end;
  total.final_regs = r.final_regs;
}

RunSummary run_impl(const Plan& plan, const RunMode& mode) {
  RunSummary total;
  for (std::size_t k = 0; k < plan.pieces.size(); ++k) {
    const Command* next = k + 1 < plan.pieces.size() ? &plan.pieces[k + 1].cmd : nullptr;
    const PieceRun r{plan.pieces[k], static_cast<std::uint32_t>(k), total.iterations, plan.from, plan.to, next};
    add(total, run_piece(r, mode));
  }
  return total;
}

}  // namespace

void GoldenRun::run_pending(const Command* next) {
  const Piece& pc = *pending_;
  const PieceRun r{pc, static_cast<std::uint32_t>(pieces_ - 1), total_.iterations, pc.from, pc.to, next};
  add(total_, run_piece(r, RunMode{&on_iter_, every_}));
}

void GoldenRun::piece(const Piece& pc) {
  if (pending_) run_pending(&pc.cmd);
  pending_ = pc;
  ++pieces_;
}

RunSummary GoldenRun::finish() {
  if (pending_) run_pending(nullptr);
  pending_.reset();
  return total_;
}

RunSummary run(const Plan& plan, const RecordFn& on_iter) { return run_impl(plan, RunMode{&on_iter, true}); }

std::vector<Iteration> run_records(const Plan& plan) {
  std::vector<Iteration> v;
  run(plan, [&](const Iteration& it) { v.push_back(it); });
  return v;
}

std::optional<Refusal> unreachable(const Plan& plan) {
  for (std::size_t k = 0; k < plan.pieces.size(); ++k) {
    const PieceRun r{plan.pieces[k], static_cast<std::uint32_t>(k), 0, plan.from, plan.to, nullptr};
    if (auto refused = reach_piece(r)) return refused;
  }
  return std::nullopt;
}

void check_reachable(const Plan& plan) {
  if (const auto refused = unreachable(plan)) throw InputError(refused->why);
}

}  // namespace dda
