// SPDX-License-Identifier: Apache-2.0
// A regression loop shared by the engines' regression drivers: random arcs back to back
// through one harness, checked edge by edge against the reference model, a share with
// random ce_i stalls and a share reset on a random edge. Every case draws from its own
// (seed, index) stream, so a run cut into shards (--shard I/N) runs the same cases, and
// the shards' JSON results (--json FILE) sum (--merge FILE...) to the unsharded totals.
#pragma once

#include <cstdint>
#include <string>

#include "tb/engines/core_driver.hpp"
#include "tb/random/dda_random.hpp"

namespace dda {

struct MixedStats {
  long arcs = 0;
  std::uint64_t iterations = 0, cycles = 0, ce_stalled = 0, resets = 0, pieces = 0, line_pieces = 0;
  // Coverage of the arcs run to their end: [start quadrant][end quadrant][direction]
  // (quadrants of the first and last piece), full turns, circles, quarter-turned
  // ellipses, rotated ones, aspect ratio above 100, lines, arcs with lattice ends (the
  // program kind), moves of the third axis (3-D lines, plunges, helices), and draws the
  // planner refused.
  long quadrant_pairs[4][4][2] = {};
  long full = 0, circles = 0, turned = 0, rotated = 0, thin = 0, lines = 0, program = 0, spatial = 0, refused = 0;
  int pairs_covered() const;
  void add(const MixedStats& o);
};

// Cases 0 .. cases-1 of the run `seed` that lie in `shard`, back to back: case i is a
// quarter arc, a whole-ellipse arc, a program arc or a move of the third axis (a 3-D
// line, a plunge or a helix; i mod 4), a, b log-uniform in
// [1, 4096]; three in sixteen with random ce_i stalls, one in eight reset on a random
// clock edge of the arc (the load edge and ce_i stalls included), after which the core
// must be idle and run the next arc. A drawn arc the planner refuses is counted and
// redrawn from the case's stream. Throws on the first mismatch, with the seed, the case
// and the arc.
MixedStats run_mixed(CoreHarness& h, std::uint64_t seed, long cases, Shard shard = {});

int regress_main(CoreHarness& h, int argc, char* argv[]);

}  // namespace dda
