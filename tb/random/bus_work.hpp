// SPDX-License-Identifier: Apache-2.0
// The same random work on any of the block's buses: random arcs (as part programs give
// them, and 3-D ones turned onto any plane of the axes) with random feed increments and
// step/dir timings, queued back to back over a master of the target's bus while the
// block runs (ce_i low a tenth of the time, glitches shorter than the input filter on
// every input, the done interrupt on), then drained. Every choice is drawn from
// the seed apart from the bus' own timing, so the work is the same on every bus: what
// the block does with it (each iteration of the core, each pulse at the pins, the
// positions) must be the same too, however fast the bus brings the commands.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/motion/bus_target.hpp"

namespace dda::motion {

struct BusWork {
  // Each iteration of the core, in order: its step_x, step_y, step_z, dir_x, dir_y,
  // dir_z bits (step_x the most significant of six).
  std::vector<std::uint8_t> iterations;
  // Each axis' step pulses at the pins (x, y, z), in order: 1 when the direction pin was
  // high (the axes' pulses interleave as their stages' timings and ce_i let them out).
  std::array<std::vector<std::uint8_t>, 3> pulses;
  Point end;                       // the position counters at the end
  Point want;                      // the arcs' end point
  Point snap;                      // SNAP_* after a CTRL.snapshot at the end
  Point snap_after_write;          // SNAP_* again after a write to SNAP_X (read-only)
  std::uint32_t entry_read = ~0u;  // ENTRY read at the end (write-only: reads 0)
  std::uint64_t cycles = 0, pieces = 0;
  bool irq_seen = false, irq_cleared = false;  // the done interrupt at the end; off once cleared
  // AXI4-Lite: the reads made while a write's response waited (BREADY low); SPI: the
  // write frames of the wrong length sent among the others (each must make no access).
  std::uint64_t reads_past_response = 0;
  int stray_frames = 0;
};

// Runs `arcs` random arcs drawn from `seed` on t through a master of `bus`; throws
// GuardError when a finished piece is not on its end point (PieceMonitor) or the
// step/dir timing breaks (StepDirMonitor).
BusWork run_bus_work(BusTarget& t, Bus bus, std::uint64_t seed, int arcs);

// "" when the two did the same, else where they part ("iteration 812: ...").
std::string compare_work(const BusWork& a, const BusWork& b);

}  // namespace dda::motion
