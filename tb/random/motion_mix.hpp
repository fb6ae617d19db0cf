// SPDX-License-Identifier: Apache-2.0
// Random work for the motion block on any bus target (the RTL harness, the
// co-simulation): batches of random arcs (as part programs give them: lattice ends, full
// turns, lines, rotated ellipses) queued back to back while the block runs, over classic
// or pipelined Wishbone cycles with random idle cycles and ce_i low a tenth of the time;
// among them partial commits, writes to a full queue, aborts and resets in the middle of
// a queue; a third of the arcs move the third axis (3-D lines, plunges, helices), two in
// three of them turned onto another plane of the axes (the entry's axes). Each batch runs with random step/dir
// timings (all 0 half of the time, small ones, and large ones, up to the fields' maximum, on a batch of short arcs
// drawn apart so the cycles stay bounded), random output polarity and a random feed increment per piece (0, the full
// rate, half of the time); a fifth of the batches are short arcs paced by the pacer instead (a random cruise speed,
// minimum speed and acceleration, the entries' exit speeds planned over the batch), with an override change and a
// feed hold and resume while they run; a quarter of the batches are cut short (an abort, a reset, an overflow, a hard
// stop, a soft stop, the watchdog running out, a machine input: an E-stop, a limit, a home switch in homing mode,
// the armed probe). Glitches shorter than the input filter fall on random inputs at random cycles throughout, with
// random input polarity and filters: the block must ignore them. Every edge passes the timing monitor (StepDirMonitor:
// the four timings, no step lost or added); every piece that finishes must leave the position counters on its end point
// (PieceMonitor), and after every batch that ran to its end they must equal the batch's start plus the arcs' moves
// (throws GuardError otherwise); the target itself checks every edge.
#pragma once

#include <cstdint>

#include "model/motion/bus_target.hpp"

namespace dda::motion {

struct MixStats {
  std::uint64_t arcs = 0, pieces = 0, batches = 0, aborts = 0, resets = 0, partial = 0, overflow = 0;
  std::uint64_t position_checks = 0, piece_checks = 0;
  std::uint64_t timed_batches = 0, large_timing_batches = 0, fed_pieces = 0, pulses = 0;
  std::uint64_t spatial = 0, pulses_z = 0;  // arcs that move the third axis, its pulses
  std::uint64_t turned = 0;                 // of those, turned onto another plane (the entry's axes)
  std::uint64_t paced_batches = 0, paced_pieces = 0, holds = 0;  // batches paced by the pacer
  std::uint64_t threshold_batches = 0;  // of those, with the pacer's comparisons at their thresholds
  std::uint64_t hard_stops = 0, soft_stops = 0, watchdogs = 0;  // batches cut short so
  std::uint64_t speed_watched = 0, speed_windows = 0;           // paced batches under the speed monitor, its windows
  double peak_speed_share = 0;                                  // the fastest window over its batch's cruise speed
  std::uint64_t glitches = 0, input_trips = 0;  // glitches on the machine's inputs; batches an input stopped
};

// Runs `arcs` random arcs drawn from `seed` (semi-axes up to max_axis).
MixStats run_motion_mix(BusTarget& t, std::uint64_t seed, std::uint64_t arcs, bool pipelined,
                        std::int64_t max_axis = 400);

}  // namespace dda::motion
