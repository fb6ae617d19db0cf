// SPDX-License-Identifier: Apache-2.0
// The pacer's options (`dda feed --feed-rate`, `dda plot --speed`), checked into the
// reference model's run (tb/measure/pace_report.hpp), and the picture files' names.
#pragma once

#include <string>

#include "tb/measure/pace_report.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace dda::cli {

// The pacer's run (`dda feed --feed-rate`, `dda plot --speed`): steps/s, steps/s^2, Hz,
// steps/s.
struct PaceCli {
  double feed_rate = 0, accel = 0, clock_hz = 0, vmin = 0;
  // Whether each was given (add_pace_options sets them up): without --vmin the minimum
  // speed is sqrt(2 accel x 1 step).
  CLI::Option *feed_opt = nullptr, *accel_opt = nullptr, *clock_opt = nullptr, *vmin_opt = nullptr;
  bool paced() const;      // --feed-rate given
  bool any_given() const;  // any of the four given
  bool vmin_given() const;
};

void add_pace_options(CLI::App* sub, PaceCli& p);
// The options checked (InputError naming the one out of range): the feed, the clock,
// the acceleration, the minimum speed (default sqrt(2 A x 1 step), at most the feed).
PaceOptions pace_options(const PaceCli& f);
// InputError, one line naming the highest feed the block follows, for a feed on a plan
// beyond it at the clock (a feed beyond a step per clock named as that first).
void check_followable(const Plan& plan, const PaceOptions& o);
// A picture's file name (option: its name in the message): not empty, not standard
// output, ending in .svg or without an extension (InputError).
void check_svg_name(const std::string& option, const std::string& path);

}  // namespace dda::cli
