// SPDX-License-Identifier: Apache-2.0
#include "tb/measure/pace_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <vector>

#include "host/driver/feed.hpp"
#include "model/datapath/errors.hpp"

namespace dda {

using motion::kNormFrac;
using motion::kRampFrac;
using motion::kSpeedFrac;
using motion::PaceEntry;
using motion::Pacer;
using motion::PaceSettings;

std::uint32_t speed_field(double steps_per_s, double clock_hz) {
  const double f = std::round(steps_per_s / clock_hz * std::ldexp(1.0, kSpeedFrac));
  if (!(f >= 0) || f > 4294967295.0) {
    throw InputError(fmt::format("pace: {} steps/s is not below one step per clock at {} Hz", steps_per_s, clock_hz));
  }
  return std::uint32_t(f);
}

std::uint64_t accel_field(double steps_per_s2, double clock_hz) {
  const double f = std::round(steps_per_s2 / (clock_hz * clock_hz) * std::ldexp(1.0, kRampFrac));
  if (!(f >= 0) || f > 4294967295.0) {
    throw InputError(
        fmt::format("pace: an acceleration of {} steps/s^2 is out of range at {} Hz", steps_per_s2, clock_hz));
  }
  return std::uint64_t(f);
}

double ramp_steps_per_s(std::uint64_t ramp_speed, double clock_hz) {
  return double(ramp_speed) / std::ldexp(1.0, kRampFrac) * clock_hz;
}

double trapezoid_seconds(double length, double feed, double accel, double vmin) {
  const double end = std::min(vmin, feed);
  const double up = feed * feed / (2 * accel), down = (feed * feed - end * end) / (2 * accel);
  if (up + down <= length) return feed / accel + (feed - end) / accel + (length - up - down) / feed;
  const double peak = std::sqrt((2 * accel * length + end * end) / 2);  // never reaches the feed
  return peak / accel + (peak - end) / accel;
}

namespace {

// The entries the driver writes: the feed as cruise speed and limit (motion::pace_entries).
std::vector<PaceEntry> entries_of(const Plan& plan, std::uint32_t cruise, std::uint32_t vmin, std::uint64_t accel) {
  std::vector<Command> cmds;
  for (const auto& p : plan.pieces) cmds.push_back(p.cmd);
  return motion::pace_entries(cmds, cruise, vmin, accel);
}

// The run's state between clocks.
struct Run {
  const Plan& plan;
  const PaceOptions& o;
  const PaceHooks& hooks;
  PaceResult res;
  PaceSettings set;
  std::vector<PaceEntry> entries;
  Pacer pacer;
  std::optional<Datapath> dp;
  std::size_t next = 0, cur = 0;
  bool stepped = false;
  std::uint64_t last_clock = 0, last_v = 0;
  PaceRow row;  // the iteration being measured

  Pacer::In inputs(std::uint64_t clock) {
    Pacer::In in;
    in.advance = true;
    in.running = dp && !dp->done();
    // The running piece's, or the finished one's (the core's registers as it left them).
    if (dp) in.norm = motion::norm_operands(plan.pieces[cur].cmd, dp->regs());
    in.stepped = stepped;
    in.take = !in.running && next < plan.pieces.size();
    if (in.take) in.entry = entries[next];
    in.next_queued = next + (in.take ? 1 : 0) < plan.pieces.size();
    if (hooks.each) hooks.each(clock, set);
    in.set = set;
    return in;
  }

  // The measurements of an iteration on this clock, before its edge.
  void measure(const Pacer::In& in, std::uint64_t clock) {
    const double d = feed::dda_speed(plan.pieces[cur].cmd, dp->regs());
    const double v = ramp_steps_per_s(pacer.speed(), o.clock_hz);
    const double path_speed = pacer.distance() ? v / (double(pacer.distance()) / std::ldexp(1.0, kNormFrac)) * d : 0;
    res.path += d;
    res.last_speed = v;
    if (pacer.distance() > 0) {
      res.peak_iteration_rate =
          std::max(res.peak_iteration_rate, v / (double(pacer.distance()) / std::ldexp(1.0, kNormFrac)));
    }
    if (res.iterations > 0 && clock > last_clock) {
      const double dv = std::fabs(double(pacer.speed()) - double(last_v));
      const double rate = ramp_steps_per_s(std::uint64_t(dv), o.clock_hz) * o.clock_hz / double(clock - last_clock);
      res.worst_speed_change = std::max(res.worst_speed_change, rate);
    }
    last_clock = clock;
    last_v = pacer.speed();
    // (An iteration paced provisionally, with the run before's d, is not one: its time is
    // corrected once the run's own d is in.)
    if (pacer.speed() == pacer.target(in) && !pacer.ramping_down() && !in.set.hold &&
        in.set.override_ == motion::kOverrideOne && d > 0 && pacer.fresh()) {
      const double want = hooks.entries ? ramp_steps_per_s(pacer.target(in), o.clock_hz) : o.feed;
      res.worst_cruise_error = std::max(res.worst_cruise_error, std::fabs(path_speed - want) / want);
      ++res.cruise_iterations;
    }
    ++res.iterations;
    row = PaceRow{res.iterations, clock, v, path_speed, res.path, Point{}};
  }

  // The piece has ended: its last iteration's speed against the speed it may leave at.
  void note_junction(const Pacer::In& in) {
    if (in.set.override_ != motion::kOverrideOne || in.set.hold) return;
    const bool follows = cur + 1 < plan.pieces.size();
    // (The pacer never goes below the minimum speed: a rest ends at it.)
    const std::uint32_t exit = std::max(follows ? entries[cur].exit : 0, set.vmin);  // x 2^kSpeedFrac
    const double allowed = ramp_steps_per_s(std::uint64_t(exit) << (kRampFrac - kSpeedFrac), o.clock_hz);
    if (!(allowed > 0)) return;
    res.worst_junction_excess = std::max(res.worst_junction_excess, res.last_speed / allowed - 1);
    ++res.junctions;
  }

  // The core's iteration on the edge: the steps, in the run's axes.
  std::array<bool, 3> iterate(std::array<bool, 3>& dir) {
    const Command& c = plan.pieces[cur].cmd;
    const Iteration r = dp->iterate();
    stepped = r.step_x || r.step_y || r.step_z;
    const Point delta = to_run_axes(Point{r.step_x ? (c.dir_x_neg ? -1 : 1) : 0, r.step_y ? (c.dir_y_neg ? -1 : 1) : 0,
                                          r.step_z ? (c.dir_z_neg ? -1 : 1) : 0},
                                    plan.pieces[cur].rot);
    res.end = res.end + delta;
    dir = {delta.x < 0, delta.y < 0, delta.z < 0};
    return {delta.x != 0, delta.y != 0, delta.z != 0};
  }

  // One clock (or a stretch of clocks on which only the phase moves); false at the end.
  bool clock(std::uint64_t& clock) {
    const Pacer::In in = inputs(clock);
    if (!in.running && !in.take) return false;
    if (!hooks.each && !hooks.clock_by_clock && !hooks.edge) {
      if (const std::uint64_t n = pacer.idle_clocks(in)) {
        pacer.skip(in, n);
        res.monitor.idle(n);
        clock += n;
        if (hooks.watch) hooks.watch(clock - 1, pacer, res.path);
        return true;
      }
    }
    const bool it = pacer.iterate(in);
    if (it) measure(in, clock);
    if (hooks.edge) hooks.edge(pacer, in);
    pacer.edge(in);
    stepped = false;
    std::array<bool, 3> step{}, dir{};
    if (it) {
      step = iterate(dir);
      if (dp->done()) note_junction(in);
      row.at = res.end;
      if (hooks.row) hooks.row(row);
    }
    res.monitor.edge(step, dir);
    if (in.take) {
      cur = next++;
      dp.emplace(plan.pieces[cur].cmd, Point{}, plan.pieces[cur].rot);
    }
    if (hooks.watch) hooks.watch(clock, pacer, res.path);
    ++clock;
    return true;
  }
};

}  // namespace

PaceResult pace_plan(const Plan& plan, const PaceOptions& o, const PaceHooks& hooks) {
  if (!(o.clock_hz > 0) || !(o.feed > 0) || !(o.accel >= 0) || !(o.vmin >= 0) || o.vmin > o.feed ||
      (o.accel > 0 && !(o.vmin > 0))) {
    throw InputError(
        "pace: the clock and the feed must be positive, the acceleration not negative, the minimum "
        "speed at most the feed and above 0 with an acceleration (the ramp would reach rest before "
        "the last piece's end)");
  }
  Run r{plan,
        o,
        hooks,
        PaceResult{0, 0, 0, 0, 0, 0, 0, 0, 0, o.clock_hz, plan.from,
                   motion::SpeedMonitor(motion::MotionLimits{o.clock_hz, o.feed, o.accel}), 0, 0},
        {},
        {},
        {},
        {},
        0,
        0,
        false,
        0,
        0,
        {}};
  r.set.accel = accel_field(o.accel, o.clock_hz);
  r.set.vmin = speed_field(o.vmin, o.clock_hz);
  const std::uint32_t cruise = speed_field(o.feed, o.clock_hz);
  if (hooks.entries) {
    if (hooks.entries->size() != plan.pieces.size()) throw GuardError("pace: one entry per piece");
    r.entries = *hooks.entries;
  } else {
    r.entries = entries_of(plan, cruise, r.set.vmin, r.set.accel);
  }
  std::uint64_t clock = 0;
  // Far beyond any run at these speeds: a run that stops short of its end is an error.
  const double slowest = o.accel > 0 ? std::min(o.vmin, o.feed) : o.feed;
  double steps = 0;
  for (const auto& p : plan.pieces) steps += double(p.cmd.cnt_x + p.cmd.cnt_y + p.cmd.cnt_z);
  const double bound = 4 * (steps + 2) / slowest * o.clock_hz + 1e6;
  while (r.clock(clock)) {
    if (double(clock) > bound) throw GuardError(fmt::format("pace: no end after {} clocks", clock));
  }
  r.res.clocks = clock;
  r.res.ideal_seconds = o.accel > 0 ? trapezoid_seconds(r.res.path, o.feed, o.accel, o.vmin) : r.res.path / o.feed;
  return r.res;
}

void write_pace_csv(std::ostream& os, const Plan& plan, const PaceOptions& o) {
  os << "iteration,clock,time_s,commanded_steps_per_s,path_steps_per_s,path_steps,x,y,z\n";
  PaceHooks h;
  h.row = [&](const PaceRow& r) {
    os << fmt::format("{},{},{:.9f},{:.3f},{:.3f},{:.4f},{},{},{}\n", r.iteration, r.clock,
                      double(r.clock) / o.clock_hz, r.commanded, r.path_speed, r.path, r.at.x, r.at.y, r.at.z);
  };
  pace_plan(plan, o, h);
}

void write_pace_report(std::ostream& os, const Plan& plan, const PaceOptions& o, bool summary,
                       const std::string& label) {
  const PaceResult r = pace_plan(plan, o);
  if (!summary) {
    os << "| arc | feed (steps/s) | acceleration (steps/s^2) | clock (Hz) | path (steps) | time (s) | ideal trapezoid "
          "(s) | time over ideal | worst feed error at cruise | commanded speed's change (of A) | pin monitor: "
          "acceleration (of A) | pin monitor: speed (of F) | last step (steps/s) | peak iteration rate (per s) |\n";
    os << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  }
  os << fmt::format(
      "| {} | {:.0f} | {:.3g} | {:.3g} | {:.1f} | {:.6f} | {:.6f} | {:+.2f}% | {:.2e} | {:.4f} | {:.3f} | "
      "{:.4f} | {:.1f} | {:.3g} |\n",
      label, o.feed, o.accel, o.clock_hz, r.path, r.seconds(), r.ideal_seconds,
      100 * (r.seconds() / r.ideal_seconds - 1), r.worst_cruise_error,
      o.accel > 0 ? r.worst_speed_change / o.accel : 0.0, o.accel > 0 ? r.monitor.peak_accel() / o.accel : 0.0,
      r.monitor.peak_speed() / o.feed, r.last_speed, r.peak_iteration_rate);
}

}  // namespace dda
