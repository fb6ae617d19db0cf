// SPDX-License-Identifier: Apache-2.0
#include "host/speed/pace_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>

#include "model/datapath/errors.hpp"
#include "model/motion/pace_params.hpp"

namespace dda::speed {

PaceSetup pace_setup(const PlannerLimits& plim, const MachineLimits& lim, program::Length step, double clock_hz) {
  if (!(clock_hz > 0)) throw InputError("the clock must be positive");
  PaceSetup s;
  s.clock_hz = clock_hz;
  s.step_mm = double(step) / double(program::kNmPerMm);
  const double a = std::round(plim.accel / s.step_mm / (clock_hz * clock_hz) * std::ldexp(1.0, motion::kRampFrac));
  if (!(a >= 1) || a >= std::ldexp(1.0, motion::kAccelWidth)) {
    throw InputError(fmt::format("the path acceleration {} mm/s^2 does not fit ACCEL at {} Hz with a {} mm step",
                                 plim.accel, clock_hz, s.step_mm));
  }
  s.accel = std::uint64_t(a);
  s.vmin = speed_word(lim.min_speed / 60, s);
  if (s.vmin == 0) throw InputError("the minimum speed is below VMIN's unit at this clock");
  return s;
}

std::uint32_t speed_word(double mm_s, const PaceSetup& s) {
  const double f = std::round(mm_s / s.step_mm / s.clock_hz * std::ldexp(1.0, motion::kSpeedFrac));
  if (!(f >= 0) || f > 4294967295.0) {
    throw InputError(fmt::format("{} mm/min is not below one step per clock at {} Hz", mm_s * 60, s.clock_hz));
  }
  return std::uint32_t(f);
}

motion::PaceEntry pace_entry(const PlannedSegment& p, const Piece& pc, const PaceSetup& s) {
  motion::PaceEntry e;
  e.cruise = e.limit = speed_word(p.cap, s);
  e.exit = speed_word(p.exit, s);
  e.length = motion::pace_length(pc.cmd);
  e.brake_exit = motion::brake_distance(e.exit, s.vmin, s.accel);
  return e;
}

PlannedProgram plan_program_pieces(std::istream& in, const std::string& file, const program::ReadOptions& read,
                                   const program::LatticeOptions& lattice, const MachineLimits& lim) {
  PlannedProgram out;
  out.plan.geometry = ProgramGeometry{lattice.preload};
  out.totals = plan_program_speeds(
      in, file, read, lattice, program::kDefaultWindow, lim, [&](const BlockSpeeds& b) { out.blocks.push_back(b); },
      [&](const PlannedSegment& p) { out.segments.push_back(p); },
      [&](const program::BlockPlan& b) {
        for (const Piece& pc : b.plan.pieces) {
          out.plan.pieces.push_back(pc);
          out.plan.iteration_bound += pc.iteration_bound;
        }
      });
  out.plan.from = out.plan.pieces.front().from;
  out.plan.to = out.plan.pieces.back().to;
  return out;
}

namespace {
// The core's pace (docs/design.md, "Pacer"), at most: an iteration takes a clock; one
// that steps also the clocks on which the core then waits (the step's edge into the
// pacer, the norm unit reading its operands, the hand-over of the run's d); and from one
// step to the next the norm unit makes the run's d, kNormLatency clocks, and hands it
// over. (The correction's clocks after the hand-over do not hold the core.)
constexpr int kIterationClocks = 1;
constexpr int kStepClocks = motion::kNormOperandEdges + 2;
constexpr int kRunClocks = motion::kNormLatency + 1;
}  // namespace

double clocks_per_path_step(std::uint64_t d, double axes) {
  const double per_iteration = d > 0 ? std::ldexp(1.0, motion::kNormFrac) / double(d) : 0;
  // Stepping iterations per path step: at most the steps (axes) and at most the
  // iterations (1 / d); each costs kStepClocks, its own clock counted with the rest, and
  // steps come at most every kRunClocks.
  const double stepping = d > 0 ? std::min(axes, per_iteration) : axes;
  return std::max((kStepClocks - kIterationClocks) * stepping + kIterationClocks * per_iteration,
                  kRunClocks * stepping);
}

double piece_clock(const PlannedSegment& p, const Command& c, double step_mm) {
  // (path steps per second at its fastest, times the clocks per path step)
  return p.peak / step_mm * clocks_per_path_step(motion::min_iteration_distance(c), axes_factor(p.seg));
}

double slowest_clock(const PlannedProgram& pp, const PlannerLimits& pl, double step_mm) {
  double need = 0;
  for (std::size_t k = 0; k < pp.segments.size(); ++k)
    need = std::max(need, piece_clock(pp.segments[k], pp.plan.pieces[k].cmd, step_mm));
  const double ramp = std::sqrt(pl.accel / step_mm * std::ldexp(1.0, motion::kRampFrac - motion::kAccelWidth));
  return std::max(need, ramp);
}

namespace {

// Calls f(need, from, to) for every stretch of a piece's path `window` steps long (the
// whole piece if shorter): need the most clocks per path step the block takes there,
// from and to its ends' distances along the path from `offset` (the path before the
// piece). The piece runs as runs of iterations, a quiet run (no step, one d) and the
// iteration that steps; the window slides over them, its oldest quiet run cut to the
// length. Returns the piece's path.
template <typename F>
double each_stretch(const Command& c, double window, double offset, F f) {
  struct Run {
    double clocks, path, d;
    bool quiet;
  };
  const double unit = std::ldexp(1.0, motion::kNormFrac);
  std::deque<Run> win;
  double clocks = 0, path = 0, gone = 0;
  bool any = false;
  const auto push = [&](const Run& run) {
    win.push_back(run);
    clocks += run.clocks;
    path += run.path;
    gone += run.path;
    while (win.size() > 1 && path - win.front().path >= window) {
      clocks -= win.front().clocks;
      path -= win.front().path;
      win.pop_front();
    }
    if (path < window) return;
    double cl = clocks, pa = path;
    const Run& first = win.front();
    if (first.quiet && win.size() > 1) {
      const double rest = path - first.path, n = std::ceil((window - rest) / first.d);
      cl += kIterationClocks * n - first.clocks;
      pa = rest + n * first.d;
    }
    any = true;
    f(cl / pa, offset + gone - pa, offset + gone);
  };
  RegState r = initial_regs(c);
  while (!finished(r)) {
    if (stalled(c, r)) throw GuardError("highest_feed: a piece that does not end");
    const double d = double(motion::iteration_distance(c, r)) / unit;
    const std::uint64_t n = quiet_iterations(c, r);
    const double quiet = double(kIterationClocks) * double(n);
    if (n > 0 && d > 0) push({quiet, double(n) * d, d, true});
    skip_quiet(c, r, n);
    push({std::max(double(kStepClocks), kRunClocks - quiet), d, d, false});  // (the iteration that steps)
    next_state(c, r);
  }
  if (!any && path > 0) f(clocks / path, offset + gone - path, offset + gone);
  return gone;
}

}  // namespace

double highest_feed(const std::vector<Command>& pieces, double clock_hz, double accel, double vmin) {
  double length = 0;
  for (const Command& c : pieces) length += each_stretch(c, HUGE_VAL, 0, [](double, double, double) {});
  double most = HUGE_VAL, offset = 0;
  for (const Command& c : pieces) {
    offset += each_stretch(c, kFeedWindow, offset, [&](double need, double from, double to) {
      const double follows = clock_hz / need;
      // The fastest the ramp lets the pacer run there, from the start and to the end.
      const double reach = accel > 0 ? std::sqrt(vmin * vmin + 2 * accel * std::min(to, length - from)) : HUGE_VAL;
      if (reach > follows) most = std::min(most, follows);
    });
  }
  return most;
}

void check_feed(const std::vector<Command>& pieces, double feed, double clock_hz, double accel, double vmin) {
  const double most = highest_feed(pieces, clock_hz, accel, vmin);
  if (feed > most) {
    throw InputError(fmt::format(
        "--feed-rate {} steps/s is beyond what the block follows on this path at {} Hz: at most {:.0f} steps/s "
        "(an iteration takes a clock, one that steps {}, and steps come at most every {} clocks; "
        "docs/design.md, \"Pacer\")",
        feed, clock_hz, std::floor(most), kStepClocks, kRunClocks));
  }
}

void check_clock(const PlannedProgram& pp, const PlannerLimits& pl, double step_mm, double clock_hz) {
  const double need = slowest_clock(pp, pl, step_mm);
  if (need > clock_hz) {
    throw InputError(
        fmt::format("the planned speeds need a clock of at least {:.0f} Hz with a {} mm step, not {} Hz: an iteration "
                    "takes a clock, one that steps {}, steps come at most every {} clocks, and ACCEL holds the path "
                    "acceleration (docs/design.md, \"Pacer\"); raise the clock, or lower the machine's speeds or "
                    "acceleration or coarsen the step",
                    std::ceil(need), step_mm, clock_hz, kStepClocks, kRunClocks));
  }
}

ProgramPacing program_pacing(const PlannedProgram& pp, const PlannerLimits& plim, const MachineLimits& lim,
                             program::Length step, double clock_hz) {
  ProgramPacing out;
  check_clock(pp, plim, double(step) / double(program::kNmPerMm), clock_hz);
  out.setup = pace_setup(plim, lim, step, clock_hz);
  out.entries = program_entries(pp, out.setup);
  return out;
}

std::vector<motion::PaceEntry> program_entries(const PlannedProgram& pp, const PaceSetup& s) {
  std::vector<motion::PaceEntry> entries;
  entries.reserve(pp.segments.size());
  for (std::size_t k = 0; k < pp.segments.size(); ++k)
    entries.push_back(pace_entry(pp.segments[k], pp.plan.pieces[k], s));
  motion::limit_exits(entries, s.vmin, s.accel);
  return entries;
}

double entries_seconds(const std::vector<motion::PaceEntry>& entries, const PaceSetup& s) {
  if (s.accel == 0 || s.vmin == 0 || !(s.clock_hz > 0)) {
    throw GuardError("entries_seconds: a setup without ACCEL, VMIN or clock (pace_setup gives them)");
  }
  // In steps, steps per clock and clocks: each piece a trapezoid (or triangle) between
  // its predecessor's exit and its own, VMIN at least, at ACCEL under its cruise speed;
  // the first from rest (the pacer ramps from 0).
  const double unit = std::ldexp(1.0, motion::kSpeedFrac);
  const double accel = double(s.accel) / std::ldexp(1.0, motion::kRampFrac);
  const double vmin = double(s.vmin) / unit;
  double clocks = 0, from = 0;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const motion::PaceEntry& e = entries[k];
    const double len = double(e.length) / std::ldexp(1.0, motion::kLenFrac);
    const double cruise = std::max(double(e.cruise) / unit, vmin);
    const double v0 = std::min(from, cruise);
    // At most what a ramp up over the whole piece reaches.
    const double v1 = std::min({std::max(k + 1 < entries.size() ? double(e.exit) / unit : 0, vmin), cruise,
                                std::sqrt(v0 * v0 + 2 * accel * len)});
    double peak = 0;
    const double whole = ramp_time(len, v0, v1, cruise, accel, &peak);
    if (peak > v1 * (1 + 1e-12)) {
      // A ramp down: the pacer ends it its margin before the piece's end and runs the
      // rest at the exit speed.
      const double margin = std::min(len, std::ldexp(1.0, -motion::kMarginShift));
      clocks += ramp_time(len - margin, v0, v1, cruise, accel, nullptr) + margin / v1;
    } else {
      clocks += whole;
    }
    from = v1;
  }
  return clocks / s.clock_hz;
}

double entries_length(const std::vector<motion::PaceEntry>& entries, const PaceSetup& s) {
  double steps = 0;
  for (const motion::PaceEntry& e : entries) steps += double(e.length) / std::ldexp(1.0, motion::kLenFrac);
  return steps * s.step_mm;
}

}  // namespace dda::speed
