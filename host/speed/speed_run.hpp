// SPDX-License-Identifier: Apache-2.0
// A part program's planned speeds as a stream: reader -> block planner (its window of
// blocks) -> segments -> lookahead (its window of pieces) -> one result per block with
// pieces, in program order. Memory: the two windows, never the program's length.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <istream>
#include <string>

#include "host/program_plan/program_plan.hpp"
#include "host/speed/lookahead.hpp"
#include "host/speed/machine_limits.hpp"
#include "host/speed/segments.hpp"

namespace dda::speed {

// A block's speeds, mm/s and s.
struct BlockSpeeds {
  program::Move move;
  std::size_t pieces = 0;
  double length = 0;  // mm
  double feed = 0;    // the speed the program asks
  double entry = 0, cruise = 0, exit = 0;
  double time = 0;    // its pieces' ramps and cruise
  double dwell = 0;   // the dwell before it (G04, and those of blocks shorter than a step)
  bool stop = false;  // it starts at rest: the program's start, a stop, a dwell or G61
  // What holds it below its feed: its slowest piece's limit (Limit::None: every piece
  // reaches the feed).
  Limit limit = Limit::None;
};

class SpeedRun {
 public:
  // on_segment, if given, sees every planned piece before its block's result.
  SpeedRun(const MachineLimits& lim, program::Machine m, program::Length step, std::string file,
           std::function<void(const BlockSpeeds&)> on_block,
           std::function<void(const PlannedSegment&)> on_segment = nullptr);
  // A block in program order; its curved pieces may be cut (SegmentBuilder::block).
  void block(program::BlockPlan& b);
  void finish();
  const PlannerLimits& limits() const { return plim_; }
  // A dwell after the last block with pieces (in blocks shorter than a step), s.
  double dwell_left() const { return dwell_; }

 private:
  void segment(const PlannedSegment& p);
  PlannerLimits plim_;
  SegmentBuilder build_;
  std::function<void(const BlockSpeeds&)> on_block_;
  std::function<void(const PlannedSegment&)> on_segment_;
  Lookahead ahead_;
  std::deque<std::pair<std::size_t, BlockSpeeds>> pending_;  // blocks with pieces in the window
  bool started_front_ = false;                               // the front block has had a piece
  double front_min_ = kInfinity;                             // its slowest limited piece's peak
  std::size_t blocks_ = 0;
  double dwell_ = 0;  // dwell of blocks without a piece, for the next one
};

// A bound on |t_x| + |t_y| + |t_z| along a piece (t its unit tangent): the sum of its
// axes' largest tangent shares, and at most the square root of the axes it moves.
double axes_factor(const Segment& s);

struct SpeedTotals {
  std::size_t blocks = 0, pieces = 0;
  double length = 0, time = 0, dwell = 0;  // mm, s (time includes every dwell)
  int plane = 170;                         // the run's plane (G17 170, G18 180, G19 190): the block's axes are its
  void add(const BlockSpeeds& b) {
    ++blocks;
    pieces += b.pieces;
    length += b.length;
    time += b.time + b.dwell;
    dwell += b.dwell;
  }
  void dwell_at_end(double s) {
    time += s;
    dwell += s;
  }
};

// Reads the program from `in` (program::open_program) and plans its speeds, calling
// on_block for each block with pieces (on_pieces, if given, sees each block with its
// pieces as cut, right after they entered the lookahead). Throws ProgramError as the reader and the
// planners do.
SpeedTotals plan_program_speeds(std::istream& in, const std::string& file, const program::ReadOptions& read,
                                const program::LatticeOptions& lattice, std::size_t window, const MachineLimits& lim,
                                const std::function<void(const BlockSpeeds&)>& on_block,
                                const std::function<void(const PlannedSegment&)>& on_segment = nullptr,
                                const std::function<void(const program::BlockPlan&)>& on_pieces = nullptr);

}  // namespace dda::speed
