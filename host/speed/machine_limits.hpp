// SPDX-License-Identifier: Apache-2.0
// A machine's motion limits, as the speed planner reads them (docs/programs.md,
// "Feeds and speeds"): per axis the largest velocity and acceleration, the rapid rate,
// the junction deviation, the speed a drive starts and stops at, and the planner's
// window. Defaults for a typical mill and lathe; a machine description file (JSON)
// changes any of them, and options change them again.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "host/program/program.hpp"

namespace dda::speed {

// Millimetres and seconds throughout: velocities in mm/min as machine builders give
// them, accelerations in mm/s^2.
struct AxisLimits {
  double vmax = 0;   // mm/min
  double accel = 0;  // mm/s^2
};

// What a live machine needs beyond its limits (`dda run`; docs/programs.md, "Running a
// program live"): per axis the steps per millimetre, the drive's step/dir timings, the
// outputs' polarity and where its limit switches sit; the inputs' sense and filters;
// the block's clock, the watchdog and the port.
struct AxisDrive {
  double steps_per_mm = 0;  // 0: not given (the lattice step, --step, decides)
  // The drive's timings, ns: step pulse high and low, direction setup and hold.
  double step_len_ns = 2000, step_space_ns = 2000, dir_setup_ns = 1000, dir_hold_ns = 1000;
  bool invert_step = false, invert_dir = false;
  // Where the limit switches close (mm, machine coordinates; the simulated machine's).
  std::optional<double> limit_neg_mm, limit_pos_mm;
};
struct LiveSettings {
  std::array<AxisDrive, 3> axes{};
  double clock_hz = 30e6;           // the block's clock (the board's)
  double watchdog_ms = 100;         // WATCHDOG: the block stops softly this long after the host's last write
  std::string port;                 // the port when --port is not given ("": none)
  std::uint32_t invert_inputs = 0;  // IN_POLARITY: a bit per input (motion::kInputs)
  double switch_filter_us = 0;      // the switches' level holds this long before it counts (0: a clock)
  double probe_filter_us = 0;       // the probe's
  bool limit_decel = false;         // IN_MODE.limit_decel: a limit stops softly (else at once)
};

struct MachineLimits {
  // X, Y, Z (a lathe's X is its radius' axis; its Y is not used).
  std::array<AxisLimits, 3> axes{};
  double rapid = 0;                  // mm/min, G00 (each axis' vmax still holds)
  double junction_deviation = 0.01;  // mm (Grbl's default)
  double min_speed = 1;              // mm/min: where a drive starts and stops (the block's VMIN)
  // The path's acceleration (the block's one ACCEL, every ramp) as a share of the
  // smallest axis acceleration; the rest is left to the centripetal acceleration of
  // curves (LinuxCNC's split on arcs: 0.5).
  double tangential_share = 0.5;
  double default_feed = 0;  // mm/min for feed moves of a program that gives no F (0: refused)
  std::size_t window = 16;  // pieces the lookahead plans over (at least 2)
  LiveSettings live;        // a live machine's drives, inputs, clock and port
};

// The defaults of docs/programs.md, "Feeds and speeds": a mill (X, Y 6000 mm/min, Z
// 3000, 500 mm/s^2 each, rapids at 6000) and a lathe (Z 6000, X 4000 mm/min, 500 mm/s^2,
// rapids at 4000).
MachineLimits default_limits(program::Machine m);

// Reads a machine description (JSON, docs/programs.md) of machine m over `base`: every
// key it gives replaces that value. Throws InputError naming the file and the key for an
// unreadable file, bad JSON, an unknown key, an axis m has not (Y on a lathe) or a value
// out of its range.
MachineLimits read_machine_config(const std::string& path, MachineLimits base, program::Machine m);
// The same from the file's text.
MachineLimits parse_machine_config(const std::string& text, const std::string& name, MachineLimits base,
                                   program::Machine m);

// Refuses (InputError naming the value and the rule) limits the planner cannot use:
// every axis the machine has with a positive vmax and accel, the rapid rate, the
// junction deviation and the minimum speed positive, the share in (0, 1), a window of
// 2 to 100000.
void check(const MachineLimits& l, program::Machine m);

// The path's acceleration, mm/s^2: the share of the smallest acceleration of the axes
// the machine has.
double path_accel(const MachineLimits& l, program::Machine m);
// What is left to curves, mm/s^2: sqrt(A^2 - a_t^2) for the smallest axis
// acceleration A (the tangential and the normal acceleration together never above any
// axis' limit).
double normal_accel(const MachineLimits& l, program::Machine m);

}  // namespace dda::speed
