// SPDX-License-Identifier: Apache-2.0
// A plan run through the pacer's reference model (model/motion/pacer.hpp) on the golden
// datapath, clock by clock, as the driver plans it: every piece at the feed, exit speeds
// from a backward pass over the arc's pieces (the minimum speed at the end), the
// lengths and braking distances the pacer needs. What it measures: the path speed at
// every iteration (the pace times the DDA's exact velocity) against the feed, the
// commanded speed's change between iterations, the speed and acceleration the speed
// monitor reads from the step pins, the time against the ideal trapezoid, the speed of
// the last step. `dda feed --feed-rate F --accel A --clock HZ` prints it
// (docs/results.md, "Motion a machine can follow").
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "host/planner/plan.hpp"
#include "host/speed/pace_plan.hpp"
#include "model/motion/pacer.hpp"
#include "tb/monitors/speed_monitor.hpp"

namespace dda {

struct PaceOptions {
  double feed = 0;   // steps/s along the path
  double accel = 0;  // steps/s^2 along the path
  double vmin = 0;   // steps/s: the minimum speed
  double clock_hz = 0;
};
// The pacer's fields for a speed, an acceleration (rounded to their units; InputError
// for one out of range) and back.
std::uint32_t speed_field(double steps_per_s, double clock_hz);
std::uint64_t accel_field(double steps_per_s2, double clock_hz);
double ramp_steps_per_s(std::uint64_t ramp_speed, double clock_hz);

// One iteration of the run.
struct PaceRow {
  std::uint64_t iteration = 0, clock = 0;
  double commanded = 0;   // steps/s: the pacer's speed
  double path_speed = 0;  // steps/s: the pace times the DDA's exact velocity over the pacer's d
  double path = 0;        // steps gone along the path (the DDA's exact velocity summed)
  Point at;               // the position after the iteration
};

struct PaceResult {
  std::uint64_t clocks = 0, iterations = 0, cruise_iterations = 0;
  double path = 0;                 // steps
  double worst_cruise_error = 0;   // |path speed - feed| / feed over the cruise iterations (paced
                                   // with their own d, not provisionally)
  double worst_speed_change = 0;   // steps/s^2: the commanded speed's change between iterations
  double last_speed = 0;           // steps/s: the commanded speed of the last iteration
  double peak_iteration_rate = 0;  // iterations/s the pace asks for: the commanded speed over d, at most
  double seconds() const { return double(clocks) / clock_hz; }
  double ideal_seconds = 0;  // trapezoid_seconds over the path
  double clock_hz = 0;
  Point end;
  motion::SpeedMonitor monitor;
  // At each piece's end (at 100% override, no hold): the commanded speed of its last
  // iteration over the speed it may leave at (its entry's exit, the minimum speed at the
  // program's end), less one: the largest (0 if none is above), and how many ends were seen.
  double worst_junction_excess = 0;
  std::uint64_t junctions = 0;
};

struct PaceHooks {
  // Before every clock: may change the settings (a hold, an override). With it the run
  // goes clock by clock; without it, it skips the clocks on which only the phase moves.
  std::function<void(std::uint64_t clock, motion::PaceSettings&)> each;
  // After every clock (or skipped stretch): the pacer and the path gone so far.
  std::function<void(std::uint64_t clock, const motion::Pacer&, double path)> watch;
  // Just before every clock's edge (clock by clock only): the pacer's inputs and
  // whether the last iteration stepped, what an RTL pacer run beside it is given.
  std::function<void(const motion::Pacer&, const motion::Pacer::In&)> edge;
  // Every iteration.
  std::function<void(const PaceRow&)> row;
  bool clock_by_clock = false;  // never skip (the skipping is checked against this)
  // The driver's own entries, one per piece (a program's planned speeds,
  // host/speed/pace_plan.hpp), instead of every piece at the feed; the feed is then the
  // monitor's speed limit, and the cruise error is measured against each entry's speed.
  const std::vector<motion::PaceEntry>* entries = nullptr;
};

// The run; the speed monitor checks the feed and the acceleration as limits (GuardError).
PaceResult pace_plan(const Plan& plan, const PaceOptions& o, const PaceHooks& hooks = {});

// The ideal trapezoid's time over a length: from rest up to the feed at accel, down to
// the minimum speed at the end (a triangle when the length is too short for the feed).
double trapezoid_seconds(double length, double feed, double accel, double vmin);

// `dda plot --speed FILE.svg --feed-rate ...`: an SVG picture of the run's commanded
// speed and path speed against the path length (each thinned to its lowest and highest
// over at most 1,200 stretches of the path: memory bounded), with the feed, the minimum
// speed and the ideal trapezoid; title: XML text, already escaped.
void write_speed_svg(std::ostream& os, const Plan& plan, const PaceOptions& o, const std::string& title);

// `dda feed --feed-rate ...`: one CSV row per iteration, or the run's summary (markdown,
// one row when summary, labelled).
void write_pace_csv(std::ostream& os, const Plan& plan, const PaceOptions& o);
void write_pace_report(std::ostream& os, const Plan& plan, const PaceOptions& o, bool summary,
                       const std::string& label);

// A program's planned speeds on the pacer's reference model (host/speed/pace_plan.hpp):
// the entries the driver writes, ACCEL the path acceleration, VMIN the minimum speed;
// the monitor's speed limit is the fastest piece's peak (InputError for a clock the
// core cannot follow: speed::check_clock).
PaceResult pace_program(const speed::PlannedProgram& pp, const speed::PaceSetup& setup, const speed::PlannerLimits& pl,
                        const speed::MachineLimits& lim, PaceHooks hooks = {});
// `dda plot --program FILE --speed FILE.svg`: that run's commanded and path speeds in
// mm/min against the path length in mm, over the plan's ramps and cruises, the
// programmed feed and the speed each piece allows; returns the run.
PaceResult write_program_speed_svg(std::ostream& os, const speed::PlannedProgram& pp, const speed::PaceSetup& setup,
                                   const speed::PlannerLimits& pl, const speed::MachineLimits& lim,
                                   const std::string& title);

}  // namespace dda
