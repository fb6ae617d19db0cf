// SPDX-License-Identifier: Apache-2.0
#include "core_driver.hpp"

#include <sstream>

#include "dda/hw_command.hpp"

namespace dda {

void CoreHarness::set_reset(bool rst_n) {
  in_.rst_n = rst_n;
  apply(in_, false);
}

void CoreHarness::set_ce(bool ce) {
  in_.ce = ce;
  apply(in_, false);
}

void CoreHarness::set_command(bool valid, const CmdFields& cmd) {
  in_.cmd_valid = valid;
  if (valid) in_.cmd = cmd;
  apply(in_, valid);
}

const Signals& CoreHarness::sample() {
  if (!have_last_) {
    last_ = read_signals();
    have_last_ = true;
  }
  return last_;
}

void CoreHarness::tick() {
  if (checking_ && !sb_) sb_ = std::make_unique<Scoreboard>(name());
  if (!checking_) sb_.reset();
  have_last_ = false;  // the registers change on the edge (also if it throws)
  const bool ready = edge();
  ++cycle_;
  if (sb_) sb_->after_edge(in_, ready, sample(), read_ports(), cycle_);
}

void reset_core(CoreHarness& h, int cycles) {
  h.set_command(false);
  h.set_ce(false);
  h.set_reset(false);
  for (int i = 0; i < cycles; ++i) h.tick();
  h.set_reset(true);
}

DriveResult drive_arc(CoreHarness& h, const Plan& plan, const DriveOptions& opt) {
  DriveResult res;
  const std::uint64_t start = h.cycle();
  const auto ce_at = [&](std::uint64_t c) { return opt.ce ? opt.ce(c) : true; };
  // Watchdog: edges with ce_i high beyond the golden run's own iterations (plus the loads
  // and a margin) mean the core is not finishing.
  const std::uint64_t limit = run(plan).iterations + 4 * plan.pieces.size() + 64;
  std::uint64_t ce_edges = 0;
  const std::size_t npieces = plan.pieces.size();

  // The pieces' commands are presented back to back: the next one as soon as the
  // previous one was taken (valid/ready: held until a rising edge where ready was high).
  std::size_t presented = 0, running = 0;
  h.set_command(true, hw::command_fields(plan.pieces[0].cmd));
  Point pos = plan.from;
  bool started = false;  // the first command was taken
  for (;;) {
    if (opt.reset_at_cycle != 0 && h.cycle() - start + 1 >= opt.reset_at_cycle) {
      reset_core(h, 1);
      res.cycles = h.cycle() - start;
      res.end = pos;
      res.was_reset = true;
      return res;
    }
    const bool ce = ce_at(h.cycle());
    ce_edges += ce;
    h.set_ce(ce);
    const bool offering = presented < npieces;
    const bool ready = offering && h.cmd_ready();
    const Signals pre = h.sample();
    h.tick();
    const Signals& post = h.sample();
    if (ready) {
      if (!started) res.initial = CoreModel::datapath_regs(post);
      started = true;
      ++presented;
      if (presented < npieces) {
        h.set_command(true, hw::command_fields(plan.pieces[presented].cmd));
      } else {
        h.set_command(false);
      }
    }
    if (!started) {
      if (h.cycle() - start > 1000) throw GuardError("watchdog: command not accepted in 1000 cycles");
      continue;
    }
    if (CoreModel::iterated(post)) {
      ++res.iterations;
      Iteration rec = CoreModel::iteration_record(pre, post);
      pos = pos + CoreModel::step_of(post);
      rec.iter = res.iterations;
      rec.piece = static_cast<std::uint32_t>(running);
      rec.pos = pos;
      if (opt.keep_records) res.records.push_back(rec);
      if (opt.reset_after != 0 && res.iterations == opt.reset_after) {
        reset_core(h, 1);
        res.cycles = h.cycle() - start;
        res.end = pos;
        res.was_reset = true;
        return res;
      }
    }
    if (CoreModel::err(post)) {
      std::ostringstream m;
      m << "core raised err_o (stall) at cycle " << h.cycle() << " after " << res.iterations << " iterations at ("
        << pos.x << ',' << pos.y << ')';
      throw GuardError(m.str());
    }
    if (CoreModel::done(post)) {
      if (opt.check && pos != plan.pieces[running].to) {
        throw MismatchError(std::string(h.name()) + " mismatch: piece " + std::to_string(running) + " ended at (" +
                            std::to_string(pos.x) + "," + std::to_string(pos.y) + ") instead of its end point");
      }
      if (++running == npieces) break;
    }
    if (ce_edges > limit) {
      std::ostringstream m;
      m << h.name() << ": watchdog: no done_o after " << ce_edges << " edges with ce_i high (" << res.iterations
        << " iterations, piece " << running << " of " << npieces << ", at (" << pos.x << ',' << pos.y << "), cycle "
        << h.cycle() << ")";
      throw GuardError(m.str());
    }
  }
  res.cycles = h.cycle() - start;
  res.end = pos;
  if (opt.check && res.end != plan.to) {
    throw MismatchError(std::string(h.name()) + " ended at (" + std::to_string(res.end.x) + "," +
                        std::to_string(res.end.y) + ") instead of the end point");
  }
  return res;
}

}  // namespace dda
