// SPDX-License-Identifier: Apache-2.0
// dda vectors --bus with the pacer (docs/vectors.md, "Bus-level sets"): entries paced at
// a feed and an acceleration, and the scenarios a machine's host runs (an override
// change, a feed hold and its end, a soft stop, the watchdog running out).
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "cli/vectors.hpp"
#include "host/driver/motion_driver.hpp"
#include "host/speed/pace_plan.hpp"
#include "model/datapath/errors.hpp"

namespace dda::vec {

bool BusCli::scenario() const {
  const auto given = [](const CLI::Option* o) { return o && o->count() > 0; };
  return (given(accel_opt) && !planned) || given(vmin_opt) || given(override_opt) || override_at || hold_at ||
         resume_at || soft_stop_at || watchdog;
}

void add_bus_pace_options(CLI::App* vectors, BusCli& c) {
  c.accel_opt = vectors->add_option(
      "--accel", c.accel,
      "with --bus --feed-rate --clock: pace the entries by the pacer, ramping at this acceleration (steps/s^2; 0: "
      "no ramp); with --program --speeds: every axis' acceleration, mm/s^2");
  c.vmin_opt = vectors->add_option("--vmin", c.vmin,
                                   "with --accel: the minimum speed, steps/s (default sqrt(2 x accel x 1 step))");
  c.override_opt = vectors->add_option("--override", c.override_pct,
                                       "with --bus: the feed override in percent, 0 to 200 (default 100)");
  vectors->add_option("--override-at", c.override_at, "with --override: the cycle it is written on (default: first)");
  vectors->add_option("--hold-at", c.hold_at, "with --bus: a feed hold (CTRL.hold) at this cycle (needs --resume-at)");
  vectors->add_option("--resume-at", c.resume_at, "with --hold-at: its end (CTRL.resume) at this cycle");
  vectors->add_option("--soft-stop-at", c.soft_stop_at, "with --bus: a soft stop (CTRL.soft_stop) at this cycle");
  vectors
      ->add_option("--watchdog", c.watchdog,
                   "with --bus: WATCHDOG written after the last commit and never again: a soft stop this many "
                   "clocks later")
      ->check(CLI::Range(std::uint32_t{1}, ~std::uint32_t{0}));
}

void bus_pace_options(const BusCli& c, BusOptions& b) {
  const auto given = [](const CLI::Option* o) { return o && o->count() > 0; };
  if (given(c.accel_opt) && !c.planned) {
    if (c.feed_rate == 0) throw InputError("--accel paces the entries at --feed-rate: give --feed-rate and --clock");
    if (!(c.accel >= 0 && c.accel <= 1e12))
      throw InputError(fmt::format("--accel = {} is out of range: steps/s^2, 0 to 1e12", c.accel));
    const double vmin = given(c.vmin_opt) ? c.vmin : std::min(c.feed_rate, std::sqrt(2 * c.accel));
    if (!(vmin >= 0 && vmin <= c.feed_rate))
      throw InputError(fmt::format("--vmin = {} is out of range: steps/s, 0 to the feed", vmin));
    if (c.accel > 0 && vmin == 0)
      throw InputError("--vmin 0 with an acceleration never ends the last piece: the ramp reaches rest before its end");
    b.paced = true;
    b.pace = PaceOptions{c.feed_rate, c.accel, vmin, c.clock_hz};
    speed_field(b.pace.feed, b.pace.clock_hz);  // refuses a feed beyond a step per clock
    accel_field(b.pace.accel, b.pace.clock_hz);
  } else if (given(c.vmin_opt)) {
    throw InputError("--vmin goes with --accel");
  }
  if (given(c.override_opt)) {
    if (!(c.override_pct >= 0 && c.override_pct <= 200))
      throw InputError(fmt::format("--override = {} is out of range: percent, 0 to 200", c.override_pct));
    b.override_ = std::uint32_t(std::lround(c.override_pct / 100 * motion::kOverrideOne));
  } else if (c.override_at) {
    throw InputError("--override-at goes with --override");
  }
  if ((c.hold_at == 0) != (c.resume_at == 0) || c.resume_at < c.hold_at)
    throw InputError("--hold-at and --resume-at go together, the resume after the hold (a held block never drains)");
  if (c.abort_after && (c.soft_stop_at || c.watchdog))
    throw InputError("--abort-after, --soft-stop-at and --watchdog each end the run: give one");
  b.override_at = c.override_at;
  b.hold_at = c.hold_at;
  b.resume_at = c.resume_at;
  b.soft_stop_at = c.soft_stop_at;
  b.watchdog = c.watchdog;
}

std::vector<motion::PaceEntry> bus_pace_entries(const std::vector<Plan>& plans, const BusOptions& b) {
  if (b.planned) return b.planned_entries;
  if (!b.paced) return {};
  std::vector<Command> cmds;
  for (const auto& p : plans)
    for (const auto& piece : p.pieces) cmds.push_back(piece.cmd);
  const PaceOptions& o = b.pace;
  speed::check_feed(cmds, o.feed, o.clock_hz, o.accel, o.vmin);
  return motion::pace_entries(cmds, speed_field(o.feed, o.clock_hz), speed_field(o.vmin, o.clock_hz),
                              accel_field(o.accel, o.clock_hz));
}

void run_bus_scenario(motion::BusMaster& m, motion::MotionDriver& d, const BusOptions& b, const std::uint64_t& cycle) {
  struct Event {
    std::uint64_t at;
    std::function<void()> act;
  };
  const auto ctrl = [&](std::string_view bit) { m.write(motion::reg_offset("CTRL"), motion::field_bit("CTRL", bit)); };
  std::vector<Event> ev;
  if (b.override_ != motion::kOverrideOne && b.override_at)
    ev.push_back({b.override_at, [&] { d.set_override(b.override_); }});
  if (b.hold_at) {
    ev.push_back({b.hold_at, [&] { d.hold(); }});
    ev.push_back({b.resume_at, [&] { d.resume(); }});
  }
  if (b.soft_stop_at) ev.push_back({b.soft_stop_at, [&] { ctrl("soft_stop"); }});
  if (b.abort_after) ev.push_back({cycle + std::uint64_t(b.abort_after), [&] { ctrl("abort"); }});
  if (b.watchdog) {
    m.write(motion::reg_offset("WATCHDOG"), b.watchdog);
    ev.push_back({cycle + b.watchdog + 2, [] {}});  // run until it has run out
  }
  std::stable_sort(ev.begin(), ev.end(), [](const Event& x, const Event& y) { return x.at < y.at; });
  std::size_t next = 0;
  for (std::uint64_t polls = 0; polls < 10000000; ++polls) {
    while (next < ev.size() && cycle >= ev[next].at) ev[next++].act();
    if (next < ev.size()) {
      m.idle(int(std::min<std::uint64_t>(ev[next].at - cycle, 64)));
      continue;
    }
    const std::uint32_t st = m.read(motion::reg_offset("STATUS"));
    const auto f = [&](std::string_view n) { return motion::get_field("STATUS", n, st) != 0; };
    if (f("empty") && !f("busy") && !f("stopping")) return;
    m.idle(16);
  }
  throw GuardError("dda vectors --bus: the queue did not drain");
}

}  // namespace dda::vec
