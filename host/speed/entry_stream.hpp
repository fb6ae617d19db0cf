// SPDX-License-Identifier: Apache-2.0
// A part program's motion-block entries as a stream (what `dda run` queues): reader ->
// block planner -> speed planner (its lookahead) -> one entry per piece, with the
// pacer's exits lowered where the pieces after it leave too little room to slow down
// (motion::limit_exits' rule, over a window). Memory: the planners' windows and this
// one, never the program's length.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <istream>
#include <string>

#include "host/speed/pace_plan.hpp"
#include "host/speed/speed_run.hpp"

namespace dda::speed {

// One piece as the block runs it: its command and axes (Piece), its pacing fields, and
// the program block it belongs to.
struct StreamEntry {
  Piece piece;
  motion::PaceEntry pace;
  double peak = 0, time = 0;  // the plan's: the speed it reaches (mm/s), its time (s)
  double clock_needed = 0;    // Hz: the slowest block clock that follows it (piece_clock)
  std::size_t block = 0;      // the program block's index among those with pieces (0-based)
  std::size_t line = 0;       // the block's source line
  double dwell = 0;           // s to wait at rest before it (G04 before its block; 0 but on a first piece)
  bool stop_before = false;   // a program stop (M00, M01) before its block: wait at rest for a resume
  bool block_end = false;     // the last piece of its block: its `to` is the block's end
  int plane = 170;            // the run's plane (the first block's): the block's axes are its u, v, normal
};

// Pairs the planned segments with their pieces and lowers the exits. The exits are those
// motion::limit_exits gives the whole program whenever the pieces after one within the
// window decide it (an exit that a shorter room would lower no further than a longer
// one); beyond `max_window` pieces still undecided, the front one is sent as if the
// pieces after the window did not exist (an exit that stops within them: slower, never
// faster than the whole program's).
class EntryStream {
 public:
  EntryStream(const PaceSetup& s, std::function<void(const StreamEntry&)> out, std::size_t max_window = 4096);
  // The speed run's callbacks (plan_program_speeds' on_segment and on_pieces).
  void segment(const PlannedSegment& p);
  void pieces(const program::BlockPlan& b);
  // The end of the program: every entry out.
  void finish();
  std::size_t held() const { return ready_.size(); }  // pieces waiting for their exit

 private:
  struct Held {
    StreamEntry e;
    std::uint32_t planned_exit = 0;
  };
  void pair();
  void flush(bool at_end);
  // The exit of ready_.front() with the back's own exit taken as planned (optimistic)
  // or as a stop within it (not): the backward pass of limit_exits.
  std::uint32_t front_exit(bool optimistic, bool at_end) const;
  PaceSetup s_;
  std::function<void(const StreamEntry&)> out_;
  std::size_t max_window_;
  std::deque<PlannedSegment> segs_;  // planned, their pieces not yet seen
  std::deque<StreamEntry> pieces_;   // pieces, their segments not yet planned
  std::deque<Held> ready_;           // paired, their exits not yet decided
  std::size_t blocks_ = 0;
  double dwell_ = 0;
  bool stop_ = false;
  int plane_ = 0;
};

// Reads the program from `in`, plans it and hands each entry to `out` in order.
// Throws ProgramError as the reader and the planners do, and InputError, naming the
// block, for a piece that needs a faster clock than the setup's (check_clock's rule).
SpeedTotals stream_program_entries(std::istream& in, const std::string& file, const program::ReadOptions& read,
                                   const program::LatticeOptions& lattice, std::size_t window, const MachineLimits& lim,
                                   const PaceSetup& setup, const std::function<void(const StreamEntry&)>& out);

}  // namespace dda::speed
