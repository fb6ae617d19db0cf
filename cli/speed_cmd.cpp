// SPDX-License-Identifier: Apache-2.0
#include "cli/speed_cmd.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <cmath>

#include "cli/options/output.hpp"
#include "host/report/speed_report.hpp"
#include "host/speed/pace_plan.hpp"
#include "tb/measure/pace_report.hpp"

namespace dda::cli {

bool SpeedCli::any_given() const {
  for (const CLI::Option* o : {accel_opt, jd_opt, rapid_opt, feed_opt, window_opt, config_opt, min_speed_opt}) {
    if (o && o->count() > 0) return true;
  }
  return false;
}

void add_speed_options(CLI::App* sub, SpeedCli& s, bool accel, bool flag) {
  if (flag)
    sub->add_flag("--speeds", s.speeds,
                  "with --program: plan the feeds (docs/programs.md, \"Feeds and speeds\") and report each block's "
                  "entry, cruise and exit speeds, its time and what limit held it, and the program's time");
  s.config_opt = sub->add_option("--machine-config", s.machine_config,
                                 "with --program: the machine's limits (JSON, docs/programs.md) over the defaults of "
                                 "--machine; implies --speeds");
  if (accel) {
    s.accel_opt = sub->add_option("--accel", s.accel,
                                  "with --program: every axis' acceleration, mm/s^2 (over the file); implies --speeds");
  }
  s.jd_opt = sub->add_option("--junction-deviation", s.junction_deviation,
                             "with --program: the junction deviation, mm (over the file); implies --speeds");
  s.rapid_opt =
      sub->add_option("--rapid", s.rapid, "with --program: the rapid rate, mm/min (over the file); implies --speeds");
  s.feed_opt = sub->add_option("--default-feed", s.default_feed,
                               "with --program: the feed, mm/min, of feed moves in a program that gives no F "
                               "(over the file); implies --speeds");
  s.min_speed_opt = sub->add_option("--min-speed", s.min_speed,
                                    "with --program: the speed a drive starts and stops at, mm/min (the block's "
                                    "VMIN; over the file); implies --speeds");
  s.window_opt = sub->add_option("--window", s.window,
                                 "with --program: the pieces the lookahead plans over (default 16; over the file); "
                                 "implies --speeds");
}

double positive(const char* name, double v) {
  if (!std::isfinite(v) || v <= 0)
    throw InputError(fmt::format("{} = {} is out of range: it must be positive", name, v));
  return v;
}

speed::MachineLimits machine_limits(const SpeedCli& s, program::Machine m) {
  speed::MachineLimits l = speed::default_limits(m);
  if (!s.machine_config.empty()) l = speed::read_machine_config(s.machine_config, l, m);
  if (s.accel_opt && s.accel_opt->count()) {
    for (speed::AxisLimits& a : l.axes) a.accel = positive("accel", s.accel);
  }
  if (s.jd_opt && s.jd_opt->count()) l.junction_deviation = positive("junction-deviation", s.junction_deviation);
  if (s.rapid_opt && s.rapid_opt->count()) l.rapid = positive("rapid", s.rapid);
  if (s.feed_opt && s.feed_opt->count()) l.default_feed = positive("default-feed", s.default_feed);
  if (s.min_speed_opt && s.min_speed_opt->count()) l.min_speed = positive("min-speed", s.min_speed);
  if (s.window_opt && s.window_opt->count()) l.window = s.window;
  speed::check(l, m);
  return l;
}

void run_speed_report(const ArcOptions& o, const SpeedCli& s) {
  if (!o.prog.given()) throw InputError("--speeds and the machine's limits go with --program");
  if (o.engine != "golden")
    throw InputError("--speeds plans the feeds in the driver: no engine runs (leave --engine out)");
  if (!o.vcd.empty()) throw InputError("--vcd goes with a run on an engine, not with --speeds");
  check_program_options(o);
  const program::BlockStatsFormat fmt =
      parse_enum<program::BlockStatsFormat>("format", o.format.empty() ? "text" : o.format,
                                            {{"text", program::BlockStatsFormat::Text},
                                             {"csv", program::BlockStatsFormat::Csv},
                                             {"json", program::BlockStatsFormat::Json}});
  const ProgramRun run = program_run(o.prog, parse_preload(o.preload), false);
  const speed::MachineLimits lim = machine_limits(s, run.read.machine);
  const auto in = program::open_program(o.prog.file);
  Output out(o.out);
  speed::SpeedReport report(out.stream(), fmt, lim, run.read.machine);
  const speed::SpeedTotals t = speed::plan_program_speeds(*in, run.file, run.read, run.lattice, run.window, lim,
                                                          [&](const speed::BlockSpeeds& b) { report.block(b); });
  report.finish(t);
  out.commit();
}

void run_program_speed_plot(const ArcOptions& o, const SpeedCli& s, const std::string& svg, const double* accel,
                            double clock_hz, const std::string& title) {
  if (o.engine != "golden" || !o.vcd.empty())
    throw InputError("--speed runs the pacer's reference model on the plan: leave --engine and --vcd out");
  if (!(clock_hz > 0 && clock_hz <= 1e10))
    throw InputError(fmt::format("--clock = {} is out of range: Hz, above 0 and at most 1e10", clock_hz));
  check_program_options(o);
  const ProgramRun run = program_run(o.prog, parse_preload(o.preload), false);
  speed::MachineLimits lim = machine_limits(s, run.read.machine);
  if (accel) {
    for (speed::AxisLimits& a : lim.axes) a.accel = positive("accel", *accel);
  }
  const speed::PlannerLimits pl = speed::planner_limits(lim, run.read.machine);
  const auto in = program::open_program(o.prog.file);
  const speed::PlannedProgram pp = speed::plan_program_pieces(*in, run.file, run.read, run.lattice, lim);
  const speed::PaceSetup setup = speed::pace_setup(pl, lim, run.lattice.step, clock_hz);
  Output out(svg);
  write_program_speed_svg(out.stream(), pp, setup, pl, lim, title);
  out.commit();
}

}  // namespace dda::cli
