// SPDX-License-Identifier: Apache-2.0
#include "cli/pace_cmd.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <vector>

#include "host/speed/pace_plan.hpp"
#include "model/datapath/errors.hpp"

namespace dda::cli {

namespace {
bool given(const CLI::Option* o) { return o != nullptr && o->count() > 0; }
}  // namespace

bool PaceCli::paced() const { return given(feed_opt); }
bool PaceCli::any_given() const { return paced() || given(accel_opt) || given(clock_opt) || given(vmin_opt); }
bool PaceCli::vmin_given() const { return given(vmin_opt); }

void add_pace_options(CLI::App* sub, PaceCli& p) {
  p.feed_opt =
      sub->add_option("--feed-rate", p.feed_rate,
                      "run the pacer's reference model at this feed, steps/s along the path (needs --accel, --clock)");
  p.accel_opt = sub->add_option("--accel", p.accel,
                                "with --feed-rate: the acceleration along the path, steps/s^2 (0: none); for a part "
                                "program's speed picture: every axis' acceleration, mm/s^2");
  p.clock_opt = sub->add_option("--clock", p.clock_hz, "with --feed-rate: the block's clock in Hz");
  p.vmin_opt =
      sub->add_option("--vmin", p.vmin,
                      "with --feed-rate: the minimum speed, steps/s, above 0 (default sqrt(2 * accel * 1 step): a stop "
                      "from it takes one step)");
}

PaceOptions pace_options(const PaceCli& f) {
  const double vmin = f.vmin_given() ? f.vmin : std::min(f.feed_rate, std::sqrt(2 * f.accel));
  // (nan fails these comparisons too.)
  if (!(f.feed_rate > 0 && f.feed_rate <= 1e9))
    throw InputError(fmt::format("--feed-rate = {} is out of range: steps/s, above 0 and at most 1e9", f.feed_rate));
  if (!(f.clock_hz > 0 && f.clock_hz <= 1e10))
    throw InputError(fmt::format("--clock = {} is out of range: Hz, above 0 and at most 1e10", f.clock_hz));
  if (!(f.accel >= 0 && f.accel <= 1e12))
    throw InputError(fmt::format("--accel = {} is out of range: steps/s^2, 0 to 1e12 (0: no ramps)", f.accel));
  if (f.accel > 0 && vmin == 0)
    throw InputError("--vmin 0 with an acceleration never ends the last piece: the ramp reaches rest before its end");
  if (!(vmin >= 0 && vmin <= f.feed_rate))
    throw InputError(fmt::format("--vmin = {} is out of range: steps/s, 0 to the feed", vmin));
  return PaceOptions{f.feed_rate, f.accel, vmin, f.clock_hz};
}

void check_followable(const Plan& plan, const PaceOptions& o) {
  speed_field(o.feed, o.clock_hz);  // a feed beyond a step per clock: named as that
  std::vector<Command> cmds;
  for (const auto& p : plan.pieces) cmds.push_back(p.cmd);
  speed::check_feed(cmds, o.feed, o.clock_hz, o.accel, o.vmin);
}

void check_svg_name(const std::string& option, const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  if (path.empty() || path == "-" || (!ext.empty() && ext != ".svg")) {
    throw InputError(option + " = '" + path + "' is invalid: plot writes SVG (a file name ending in .svg)");
  }
}

}  // namespace dda::cli
