// SPDX-License-Identifier: Apache-2.0
// A program's planned speeds as the motion block's pacing (docs/design.md, "Pacing in
// the block"): ACCEL the path acceleration, VMIN the machine's minimum speed, and per
// piece an entry whose cruise speed and limit are the speed the piece may reach, whose
// exit speed is the plan's (a rest: 0, the pacer ends at VMIN), with the piece's length
// as the pacer counts it and the exit's braking distance. Speeds in path steps: mm/s
// over the step.
#pragma once

#include <cstdint>
#include <vector>

#include "host/planner/plan.hpp"
#include "host/speed/lookahead.hpp"
#include "host/speed/machine_limits.hpp"
#include "host/speed/speed_run.hpp"
#include "model/motion/pacer.hpp"

namespace dda::speed {

struct PaceSetup {
  double clock_hz = 0;
  double step_mm = 0;
  std::uint64_t accel = 0;  // ACCEL
  std::uint32_t vmin = 0;   // VMIN
};
// The block's settings for the plan at a clock (InputError when a speed or the
// acceleration does not fit the pacer's fields at that clock).
PaceSetup pace_setup(const PlannerLimits& plim, const MachineLimits& lim, program::Length step, double clock_hz);
// A speed in mm/s as an entry's field (x 2^kSpeedFrac path steps per clock).
std::uint32_t speed_word(double mm_s, const PaceSetup& s);
motion::PaceEntry pace_entry(const PlannedSegment& p, const Piece& pc, const PaceSetup& s);

// A whole program planned in memory (tests and vector sets): its pieces after the cuts,
// back to back, and their planned segments in the same order.
struct PlannedProgram {
  Plan plan;
  std::vector<PlannedSegment> segments;
  std::vector<BlockSpeeds> blocks;
  SpeedTotals totals;
};
PlannedProgram plan_program_pieces(std::istream& in, const std::string& file, const program::ReadOptions& read,
                                   const program::LatticeOptions& lattice, const MachineLimits& lim);

// The slowest block clock that follows a plan at a step, Hz. Each piece at its peak
// speed v (path steps/s) asks up to v / d iterations per second, each at least a
// clock, d its shortest path per iteration (min_iteration_distance: this runs each
// piece through the datapath once), and among them up to v * min(axes_factor, 1 / d)
// stepping ones, each taking kNormOperandEdges + 2 clocks and at least
// kNormLatency + 1 from the one before (the norm unit makes the run's path length per
// iteration meanwhile); the path acceleration must also fit ACCEL (pace_setup). A
// slower clock leaves a backlog the core then works off above the commanded speed. At
// 100% override: an override above it needs the clock raised as much; step/dir timings
// longer than kNormLatency + 1 clocks a step are not counted.
double slowest_clock(const PlannedProgram& pp, const PlannerLimits& pl, double step_mm);
// The clock one planned piece (command c) needs by that rule, Hz.
double piece_clock(const PlannedSegment& p, const Command& c, double step_mm);
// InputError, with the clock needed, for a setup's clock below slowest_clock.
void check_clock(const PlannedProgram& pp, const PlannerLimits& pl, double step_mm, double clock_hz);

// The clocks the block takes at most per path step on a piece whose shortest path per
// iteration is d (x 2^kNormFrac steps, motion::min_iteration_distance; 0: none moves)
// and whose axis steps per path step are at most axes: 1 / d iterations of at least a
// clock, among them up to min(axes, 1 / d) stepping ones of kNormOperandEdges + 2
// clocks, each at least kNormLatency + 1 clocks after the one before.
double clocks_per_path_step(std::uint64_t d, double axes);
// The highest path feed, steps/s, the block follows on pieces run back to back at one
// cruise speed at a clock, with a ramp at accel from and to vmin (steps/s^2, steps/s;
// accel 0: the speed jumps): over every stretch of kFeedWindow path steps, the clock
// over the most clocks the block takes per path step there (each iteration at least a
// clock, one that steps kNormOperandEdges + 2 and at least kNormLatency + 1 after the
// one before, each moving d along the path: motion::iteration_distance before it),
// where the ramp lets the pacer run faster than that. This runs each piece through the datapath twice, a step at a
// time; infinity when nothing limits it.
double highest_feed(const std::vector<Command>& pieces, double clock_hz, double accel, double vmin);
// The stretch highest_feed measures, path steps: long enough that a stepping
// iteration more or less at its ends moves its figure by a few percent at most, short
// against the speed monitor's windows (hundreds of steps at such feeds).
inline constexpr double kFeedWindow = 32;
// InputError, one line naming highest_feed, for a feed above it: a single arc's or
// line's `--feed-rate` the block would fall short of.
void check_feed(const std::vector<Command>& pieces, double feed, double clock_hz, double accel, double vmin);

// The block's pacing of a planned program at a clock: ACCEL, VMIN and one entry per
// piece, in the plan's order (InputError as pace_setup and check_clock).
struct ProgramPacing {
  PaceSetup setup;
  std::vector<motion::PaceEntry> entries;
};
// Every piece's entry (pace_entry), the exits lowered by motion::limit_exits where the
// pacer's own lengths (the DDA's path, which at a coarse step can be shorter than the
// programmed one a piece was planned on) leave too little room to slow down to the next
// pieces' exits.
std::vector<motion::PaceEntry> program_entries(const PlannedProgram& pp, const PaceSetup& s);
// The time the entries take on their own terms, s: each piece from its predecessor's
// exit speed to its own (at least VMIN; the first from rest, the last to VMIN) at
// ACCEL under its cruise speed, over the pacer's length, a ramp down ending the pacer's
// margin (2^-kMarginShift step) early: the plan's profile on the DDA's path with drives
// that stop at VMIN, as the pacer runs it but for its clocks. GuardError for a setup
// without ACCEL, VMIN or a clock.
double entries_seconds(const std::vector<motion::PaceEntry>& entries, const PaceSetup& s);
// The pieces' path as the pacer counts it (the DDA's), mm.
double entries_length(const std::vector<motion::PaceEntry>& entries, const PaceSetup& s);
ProgramPacing program_pacing(const PlannedProgram& pp, const PlannerLimits& plim, const MachineLimits& lim,
                             program::Length step, double clock_hz);

}  // namespace dda::speed
