// SPDX-License-Identifier: Apache-2.0
// Feed rate: the planner's side of the motion block's feed generator (docs/design.md,
// "Feed"). The block iterates the core at increment / 2^kFeedWidth iterations per clock;
// a piece's speed along its path per iteration varies (the DDA's integrands are the
// velocity), so the planner turns a feed in steps per second along the path into each
// piece's increment from the piece's own iterations and path length, for a given clock.
// Floating point is fine here: this is planning, not the datapath. Acceleration ramps
// are the host's business (split a move into pieces at rising increments).
#pragma once

#include <cstdint>
#include <vector>

#include "model/datapath/datapath.hpp"

namespace dda::feed {

// The DDA's smooth speed along the path before an iteration, steps per iteration, from
// its registers: |(jv_x, jv_y) / cap, jv_z / cap_z| (an axis whose counter is done or
// whose integrand is not positive adds 0). The pacer's norm unit computes the same in
// fixed point (motion::iteration_distance).
double dda_speed(const Command& c, const RegState& r);

// What one piece does, from the golden datapath.
struct PieceMotion {
  std::uint64_t iterations = 0;
  std::uint64_t steps_x = 0, steps_y = 0, steps_z = 0;
  // The length of the curve the piece follows, in steps: the sum over its iterations of
  // the DDA's velocity |(jv_x, jv_y)| / cap (a staircase count of the steps, 1 per axial
  // and sqrt 2 per diagonal step, would overstate it by up to a quarter on a circle).
  double path = 0;
  // The DDA's smooth speed along the path, |(jv_x, jv_y)| / cap steps per iteration, over
  // the piece's iterations: smallest, largest and mean (the integrands as the iteration
  // used them; an axis whose counter is done or whose integrand is not positive adds 0).
  double speed_min = 0, speed_max = 0, speed_mean = 0;
};
PieceMotion piece_motion(const Command& c);

// The increment that runs a piece at feed_steps_per_s along its path on a block clocked
// at clock_hz: round(2^kFeedWidth * iterations * feed / (path * clock)), the piece's mean
// speed along its curve then being the feed; 2^kFeedWidth (one iteration per clock) is
// increment 0, the core's full rate. Throws InputError if that needs more than one
// iteration per clock or less than one per 2^kFeedWidth clocks, or for a non-positive
// feed or clock. The step/dir stages can hold the core below this pace when the drive's
// timings are slower than the feed (the figures in docs/results.md).
std::uint32_t feed_increment(const PieceMotion& m, double feed_steps_per_s, double clock_hz);

}  // namespace dda::feed
