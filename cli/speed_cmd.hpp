// SPDX-License-Identifier: Apache-2.0
// The speed planner's options on `dda stats --program` (docs/programs.md, "Feeds and
// speeds"): --speeds, the machine description file and the limits in millimetres that
// override it, and the report they make.
#pragma once

#include <string>

#include "cli/options/arc_options.hpp"
#include "host/speed/machine_limits.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace dda::cli {

struct SpeedCli {
  bool speeds = false;
  std::string machine_config;
  double accel = 0, junction_deviation = 0, rapid = 0, default_feed = 0, min_speed = 0;
  std::size_t window = 0;
  CLI::Option *accel_opt = nullptr, *jd_opt = nullptr, *rapid_opt = nullptr, *feed_opt = nullptr, *window_opt = nullptr,
              *config_opt = nullptr, *min_speed_opt = nullptr;
  bool any_given() const;  // a limit option or the file given
  bool wanted() const { return speeds || any_given(); }
};

// A limit's value, refused (InputError naming it) unless finite and above 0.
double positive(const char* name, double v);
// The options on `sub`; without `accel` and `flag`, those of `plot --speed`, whose
// --accel is the pacer's (in mm/s^2 with --program) and which always plans.
void add_speed_options(CLI::App* sub, SpeedCli& s, bool accel = true, bool flag = true);
// The machine's limits: its defaults, the file over them, the options over both
// (InputError for a bad file or value).
speed::MachineLimits machine_limits(const SpeedCli& s, program::Machine m);
// dda stats --program FILE --speeds: the speed report into --out (InputError when the
// options do not go together).
void run_speed_report(const ArcOptions& o, const SpeedCli& s);
// dda plot --program FILE --speed OUT.svg [--accel MM_PER_S2] [--clock HZ]: the plan on
// the pacer's reference model, drawn (accel: the option's value when given).
void run_program_speed_plot(const ArcOptions& o, const SpeedCli& s, const std::string& svg, const double* accel,
                            double clock_hz, const std::string& title);

}  // namespace dda::cli
