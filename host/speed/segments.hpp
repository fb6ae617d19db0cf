// SPDX-License-Identifier: Apache-2.0
// A program's blocks as the speed planner's segments (lookahead.hpp): each piece of a
// block (one hardware command) with its length, tangents, axis shares and smallest
// radius of curvature from the block's programmed geometry between the piece's lattice
// ends, and the speed the program asks for it: F by its feed mode and unit, the rapid
// rate for G00. Rests: at the program's start, after a stop (M00, M01), a dwell (G04)
// and a block in exact stop (G61).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "host/program_plan/program_plan.hpp"
#include "host/speed/lookahead.hpp"
#include "host/speed/machine_limits.hpp"

namespace dda::speed {

// The speed a block asks, mm/s: G00 the rapid rate; F in mm or inch per minute (G94),
// per revolution at the spindle speed S (G95, G97), or inverse time (G93: the block's
// `length_mm` in 1/F minutes); a feed move of a program that gives no F takes the
// default feed. Throws ProgramError naming the block: no feed and no default, a feed
// per revolution with no S, or with constant surface speed (G96: the feed would follow
// the radius along the move).
double block_feed(const program::Move& mv, double length_mm, const MachineLimits& lim, const std::string& file);

// The planner's limits from a machine's (mm/min to mm/s; the path and normal
// accelerations of machine_limits.hpp).
PlannerLimits planner_limits(const MachineLimits& lim, program::Machine m);
// The machine axis (0 X, 1 Y, 2 Z) of a plane's u, v and normal w (G17 170, G18 180,
// G19 190): the block's X, Y and Z in a run on that plane.
std::array<std::size_t, 3> machine_axes(int plane);

// A piece's geometry from its block: length (mm), tangents, axis shares and smallest
// radius of curvature; feed, rests and deviation left to the caller.
Segment piece_segment(const program::BlockPlan& b, const Piece& pc, program::Length step);

class SegmentBuilder {
 public:
  SegmentBuilder(const MachineLimits& lim, const PlannerLimits& plim, program::Length step, std::string file);
  // The segments of a block in path order (none for a block without a piece: a move
  // shorter than a step, whose rest and dwell pass to the next block's first piece).
  // A curved piece whose curvature holds its speed below the feed is cut where that
  // limit changes by more than 4%, at steps of its run (the parts' commands are the
  // datapath's registers there: the path is the same, step for step): b's pieces are
  // replaced by the parts, one segment each, and its first_piece counts the parts of the
  // blocks before it.
  std::vector<Segment> block(program::BlockPlan& b, std::size_t index);

 private:
  void cut(const program::BlockPlan& b, const Piece& pc, const Segment& seg, double feed, std::vector<Piece>& pieces,
           std::vector<Segment>& segs) const;
  MachineLimits lim_;
  PlannerLimits plim_;
  program::Length step_;
  std::string file_;
  bool rest_ = true;        // the next piece starts at rest
  std::size_t pieces_ = 0;  // the pieces of the blocks so far, after the cuts
};

}  // namespace dda::speed
