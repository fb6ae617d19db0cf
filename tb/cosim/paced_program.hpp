// SPDX-License-Identifier: Apache-2.0
// A part program at its planned speeds through a motion block (any BusTarget: the
// co-simulation of the SystemC model and the RTL, or the reference model alone), driven
// as firmware drives it, with the speed monitor on the step and direction pins: the path
// speed and acceleration and each axis' own, against the machine's limits.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "host/speed/pace_plan.hpp"
#include "model/motion/bus_target.hpp"
#include "tb/monitors/speed_monitor.hpp"

namespace dda::motion {

// The pins' limits for a planned program (steps/s and steps/s^2): the path's speed the
// fastest planned segment's peak and its acceleration the planner's; each pin's speed
// the vmax of the machine axis it drives (the block's X, Y, Z are the run's plane's u,
// v and normal: a lathe's G18 drives Z, X, Y) and its acceleration that axis' limit
// (the ramps' and the curves' together). An absent axis (vmax 0) is not checked.
MotionLimits pin_limits(const speed::PlannedProgram& pp, const speed::PlannerLimits& pl,
                        const speed::MachineLimits& lim, double step_mm, double clock_hz);

struct PacedRunOptions {
  std::uint64_t seed = 1;  // the master's idle cycles and the driver's write order
  bool pipelined = false;  // Wishbone cycles
  StageTimings timing;     // every axis' step/dir timings
};

struct PacedRun {
  std::uint64_t cycles = 0;  // from the reset to the drained queue
  Point position;            // read back from the block at the end
  SpeedMonitor monitor;      // the figures at the pins
};

// Resets the block, writes the timings, ACCEL and VMIN, presets the start, queues every
// piece with its entry and drains the queue, the monitor watching from the reset (a
// window over its limits throws GuardError; so does a co-simulation mismatch).
PacedRun run_paced_program(BusTarget& t, const speed::PlannedProgram& pp, const speed::ProgramPacing& pace,
                           const MotionLimits& pins, const PacedRunOptions& opt);

}  // namespace dda::motion
