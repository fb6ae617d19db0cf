// SPDX-License-Identifier: Apache-2.0
#include "host/speed/entry_stream.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/datapath/errors.hpp"
#include "model/motion/pace_params.hpp"

namespace dda::speed {

EntryStream::EntryStream(const PaceSetup& s, std::function<void(const StreamEntry&)> out, std::size_t max_window)
    : s_(s), out_(std::move(out)), max_window_(std::max<std::size_t>(max_window, 2)) {}

void EntryStream::segment(const PlannedSegment& p) {
  segs_.push_back(p);
  pair();
}

void EntryStream::pieces(const program::BlockPlan& b) {
  // (A dwell before a block without pieces waits before the next one: SpeedRun's rule.)
  dwell_ += b.move.dwell;
  stop_ = stop_ || b.move.stop;
  if (b.plan.pieces.empty()) return;
  const std::size_t index = blocks_++;
  if (plane_ == 0) plane_ = b.move.plane;
  for (std::size_t k = 0; k < b.plan.pieces.size(); ++k) {
    StreamEntry e;
    e.piece = b.plan.pieces[k];
    e.block = index;
    e.line = b.move.pos.line;
    e.dwell = k == 0 ? dwell_ : 0;
    e.stop_before = k == 0 && stop_;
    e.block_end = k + 1 == b.plan.pieces.size();
    e.plane = plane_;
    pieces_.push_back(std::move(e));
  }
  dwell_ = 0;
  stop_ = false;
  pair();
}

void EntryStream::pair() {
  while (!segs_.empty() && !pieces_.empty()) {
    Held h{std::move(pieces_.front()), 0};
    const PlannedSegment& p = segs_.front();
    h.e.pace = pace_entry(p, h.e.piece, s_);
    h.e.peak = p.peak;
    h.e.time = p.time;
    h.e.clock_needed = piece_clock(p, h.e.piece.cmd, s_.step_mm);
    h.planned_exit = h.e.pace.exit;
    ready_.push_back(std::move(h));
    segs_.pop_front();
    pieces_.pop_front();
  }
  flush(false);
}

std::uint32_t EntryStream::front_exit(bool optimistic, bool at_end) const {
  const std::uint64_t margin = std::uint64_t{1} << (motion::kLenFrac - motion::kMarginShift);
  const std::size_t n = ready_.size();
  std::uint32_t exit = 0, brake = 0;  // of the entry after the one at hand
  for (std::size_t k = n; k-- > 0;) {
    const std::uint32_t planned = ready_[k].planned_exit;
    if (s_.accel == 0) {  // (without a ramp the speed jumps: no exit is lowered)
      exit = planned;
    } else if (k + 1 == n) {
      // The program's last entry keeps its exit (it ends at VMIN); another one, with
      // nothing after it yet: its own planned exit, or a stop within nothing.
      exit = at_end || optimistic ? planned : std::min(planned, s_.vmin);
    } else {
      const std::uint64_t room =
          std::uint64_t(ready_[k + 1].e.pace.length) + (at_end && k + 2 == n ? 0 : std::uint64_t(brake));
      exit = room >= margin ? motion::fastest_within(planned, room - margin, s_.vmin, s_.accel)
                            : std::min(planned, s_.vmin);
    }
    brake = motion::brake_distance(exit, s_.vmin, s_.accel);
  }
  return exit;
}

void EntryStream::flush(bool at_end) {
  while (!ready_.empty()) {
    std::uint32_t exit = 0;
    if (at_end) {
      exit = front_exit(true, true);
    } else {
      if (ready_.size() < 2) return;
      const std::uint32_t hi = front_exit(true, false), lo = front_exit(false, false);
      if (hi != lo && ready_.size() < max_window_) return;  // the pieces to come decide it
      exit = lo;
    }
    StreamEntry e = std::move(ready_.front().e);
    ready_.pop_front();
    e.pace.exit = exit;
    e.pace.brake_exit = motion::brake_distance(exit, s_.vmin, s_.accel);
    out_(e);
  }
}

void EntryStream::finish() {
  if (!segs_.empty() || !pieces_.empty())
    throw GuardError(
        fmt::format("entry stream: {} planned segments and {} pieces left unpaired", segs_.size(), pieces_.size()));
  flush(true);
}

SpeedTotals stream_program_entries(std::istream& in, const std::string& file, const program::ReadOptions& read,
                                   const program::LatticeOptions& lattice, std::size_t window, const MachineLimits& lim,
                                   const PaceSetup& setup, const std::function<void(const StreamEntry&)>& out) {
  EntryStream stream(setup, [&](const StreamEntry& e) {
    if (e.clock_needed > setup.clock_hz) {
      throw InputError(fmt::format(
          "{}:{}: the planned speed needs a clock of at least {:.0f} Hz with a {} mm step, not {} Hz: an iteration "
          "takes a clock, one that steps {}, steps come at most every {} clocks (docs/design.md, \"Pacer\"); raise "
          "the clock, or lower the machine's speeds or coarsen the step",
          file, e.line, std::ceil(e.clock_needed), setup.step_mm, setup.clock_hz, motion::kNormOperandEdges + 2,
          motion::kNormLatency + 1));
    }
    out(e);
  });
  SpeedTotals t = plan_program_speeds(
      in, file, read, lattice, window, lim, [](const BlockSpeeds&) {},
      [&](const PlannedSegment& p) { stream.segment(p); }, [&](const program::BlockPlan& b) { stream.pieces(b); });
  stream.finish();
  return t;
}

}  // namespace dda::speed
