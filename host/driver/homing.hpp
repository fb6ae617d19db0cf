// SPDX-License-Identifier: Apache-2.0
// The homing and probing cycles of the driver (docs/design.md, "Machine inputs"), on a
// motion block's registers through a MotionDriver: moves along one axis queued with
// the golden planner's line pieces, paced at a cruise speed with the block's ACCEL and
// VMIN, stopped by the block itself (IN_MODE) when the home or probe input turns active.
#pragma once

#include <cstdint>

#include "host/driver/motion_driver.hpp"

namespace dda::motion {

struct HomingParams {
  char axis = 'x';
  bool positive = false;           // the switch lies on the positive side
  std::int64_t search_steps = 0;   // the search's longest move; no switch within it: an error
  std::int64_t backoff_steps = 0;  // back off this far from the first latch, then approach
  std::uint32_t search_speed = 0;  // cruise speeds, x 2^kSpeedFrac steps per clock
  std::uint32_t latch_speed = 0;   // the second, slower approach
  std::int32_t home_position = 0;  // the position the switch's edge is given
};
struct HomingResult {
  std::int32_t first_latch = 0, second_latch = 0;  // LATCH_<axis> of each approach
  std::int32_t shift = 0;                          // what the position register moved by
};
// Homes one axis: search toward the switch at search_speed until the block stops on its
// edge (IN_MODE.home_<axis>: a soft stop at ACCEL), back off backoff_steps from that
// latch, approach at latch_speed, and preset the axis' position so that the second
// latch reads home_position. Leaves IN_MODE as it found it and TRIP clear. Throws
// GuardError naming what failed: no switch within search_steps, still on the switch
// after backing off, no switch on the approach, the block stopped by something else.
HomingResult home_axis(MotionDriver& d, const HomingParams& p);

// A G38.2 probing move: arms the probe with IN_MODE.probe_stop, moves by `delta` at a
// cruise speed, and returns PROBE_* once the probe stopped it (the block then rests,
// past it by its braking distance). No contact over the whole move: GuardError.
Point probe_move(MotionDriver& d, Point delta, std::uint32_t speed);

// Queues a straight move by `delta` (the golden planner's pieces), paced at `speed` with
// the block's ACCEL and VMIN (read from it); on a block without the pacer (the driver
// has read the build), each piece at the feed increment that runs it at `speed`.
void queue_move(MotionDriver& d, Point delta, std::uint32_t speed);

}  // namespace dda::motion
