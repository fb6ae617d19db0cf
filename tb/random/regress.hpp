// SPDX-License-Identifier: Apache-2.0
// A regression loop shared by the engines' regression drivers: random arcs back to back
// through one harness, in lockstep with the golden model, a share with random ce_i
// stalls and a share reset halfway. Prints the numbers of arcs, iterations and cycles
// compared; returns the process exit status (0, or 1 on the first mismatch).
#pragma once

#include <cstdint>

#include "core_driver.hpp"

namespace dda {

struct MixedStats {
  long arcs = 0;
  std::uint64_t iterations = 0, cycles = 0, ce_stalled = 0, resets = 0, pieces = 0;
  // Coverage of the arcs run to their end: [start quadrant][end quadrant][direction]
  // (quadrants of the first and last piece), full turns, circles, quarter-turned
  // ellipses, aspect ratio above 100.
  long quadrant_pairs[4][4][2] = {};
  long full = 0, circles = 0, turned = 0, rotated = 0, thin = 0;
  int pairs_covered() const;
};

// `arcs` random arcs back to back (a, b log-uniform in [1, 4096]; quarter arcs and
// whole-ellipse arcs alternately), three in sixteen with random ce_i stalls, one in
// eight reset on a random clock edge of the arc (half of those during stalls) (the load edge and ce_i stalls included),
// after which the core must be idle and run the next arc. Throws on the first mismatch, with the seed and the arc.
MixedStats run_mixed(CoreHarness& h, std::uint64_t seed, long arcs);

int regress_main(CoreHarness& h, int argc, char* argv[]);

}  // namespace dda
