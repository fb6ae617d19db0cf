// SPDX-License-Identifier: Apache-2.0
#include "tb/engines/core_driver.hpp"

#include <sstream>
#include <utility>

#include "model/datapath/hw_command.hpp"

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

CoreDrive::CoreDrive(CoreHarness& h, const DriveOptions& opt, std::function<void(const Iteration&)> on_record,
                     std::function<void(const RegState&)> on_initial)
    : h_(h), opt_(opt), on_record_(std::move(on_record)), on_initial_(std::move(on_initial)), start_(h.cycle()) {}

void CoreDrive::present(const Piece& pc) {
  if (pieces_ == 0) pos_ = from_ = pc.from;
  ++pieces_;
  limit_ += pc.iteration_bound + 4;
  h_.set_command(true, hw::command_fields(pc.cmd));
  running_.push_back(pc);
  offering_ = true;
}

void CoreDrive::piece(const Piece& pc) {
  if (res_.was_reset) return;
  while (offering_) {
    if (!edge()) return;
  }
  present(pc);
}

DriveResult CoreDrive::finish() {
  while (!res_.was_reset && offering_) {
    if (!edge()) break;
  }
  if (!res_.was_reset) h_.set_command(false);
  while (!res_.was_reset && !running_.empty()) {
    if (!edge()) break;
  }
  if (!res_.was_reset) {
    res_.cycles = h_.cycle() - start_;
    res_.end = pos_;
  }
  return std::move(res_);
}

bool CoreDrive::edge() {
  const auto stop = [&] {
    reset_core(h_, 1);
    res_.cycles = h_.cycle() - start_;
    res_.end = pos_;
    res_.was_reset = true;
    return false;
  };
  if (opt_.reset_at_cycle != 0 && h_.cycle() - start_ + 1 >= opt_.reset_at_cycle) return stop();
  const bool ce = opt_.ce ? opt_.ce(h_.cycle()) : true;
  ce_edges_ += ce;
  h_.set_ce(ce);
  const bool ready = offering_ && h_.cmd_ready();
  const Signals pre = h_.sample();
  h_.tick();
  const Signals& post = h_.sample();
  if (ready) {
    if (!started_) {
      res_.initial = CoreModel::datapath_regs(post);
      if (on_initial_) on_initial_(res_.initial);
    }
    started_ = true;
    offering_ = false;
  }
  if (!started_) {
    if (h_.cycle() - start_ > 1000) throw GuardError("watchdog: command not accepted in 1000 cycles");
    return true;
  }
  if (CoreModel::iterated(post)) {
    ++res_.iterations;
    Iteration rec = CoreModel::iteration_record(pre, post);
    // (The iteration is the front piece's: its core axes drive the run's turned by its rot.)
    const int rot = running_.empty() ? 0 : running_.front().rot;
    pos_ = pos_ + to_run_axes(CoreModel::step_of(post), rot);
    rec.iter = res_.iterations;
    rec.piece = done_pieces_;
    rec.pos = pos_;
    if (on_record_) on_record_(rec);
    if (opt_.keep_records) res_.records.push_back(rec);
    if (opt_.reset_after != 0 && res_.iterations == opt_.reset_after) return stop();
  }
  if (CoreModel::err(post)) {
    std::ostringstream m;
    m << "core raised err_o (stall) at cycle " << h_.cycle() << " after " << res_.iterations << " iterations at ("
      << pos_.x << ',' << pos_.y << ')';
    throw GuardError(m.str());
  }
  if (CoreModel::done(post) && !running_.empty()) {
    if (opt_.check && pos_ != running_.front().to) {
      throw MismatchError(std::string(h_.name()) + " mismatch: piece " + std::to_string(done_pieces_) + " ended at (" +
                          std::to_string(pos_.x) + "," + std::to_string(pos_.y) + ") instead of its end point");
    }
    running_.pop_front();
    ++done_pieces_;
  }
  if (ce_edges_ > (opt_.watchdog ? opt_.watchdog : limit_)) {
    std::ostringstream m;
    m << h_.name() << ": watchdog: no done_o after " << ce_edges_ << " edges with ce_i high (" << res_.iterations
      << " iterations, piece " << done_pieces_ << " of " << pieces_ << ", at (" << pos_.x << ',' << pos_.y
      << "), cycle " << h_.cycle() << ")";
    throw GuardError(m.str());
  }
  return true;
}

DriveResult drive_arc(CoreHarness& h, const Plan& plan, const DriveOptions& opt) {
  DriveOptions o = opt;
  // Watchdog: edges with ce_i high beyond the golden run's own iterations (plus the loads
  // and a margin) mean the core is not finishing.
  if (o.watchdog == 0) o.watchdog = run(plan).iterations + 4 * plan.pieces.size() + 64;
  CoreDrive d(h, o);
  for (const Piece& pc : plan.pieces) d.piece(pc);
  DriveResult res = d.finish();
  if (!res.was_reset && opt.check && res.end != plan.to) {
    throw MismatchError(std::string(h.name()) + " ended at (" + std::to_string(res.end.x) + "," +
                        std::to_string(res.end.y) + ") instead of the end point");
  }
  return res;
}

}  // namespace dda
