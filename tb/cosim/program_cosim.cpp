// SPDX-License-Identifier: Apache-2.0
// Part programs at their planned speeds on the motion block's co-simulation: the
// SystemC model and the RTL (verilator --sc) on one clock, compared with each other and
// with the block's reference model at every edge (tb/cosim/motion_cosim.hpp), driven as
// firmware drives the block (tb/cosim/paced_program.hpp), with the speed monitor on the
// RTL's step and direction pins: the path's speed and acceleration and each axis' own
// against the machine's limits. A program file (and the machine and start it runs with),
// or generated programs of lines, arcs and ellipses at random angles (--random N:
// tb/random/random_program.hpp). One line per program; exit 1 at the first mismatch,
// limit exceeded, wrong end point, or the pacer 1% over an exit speed or off the plan's
// cruise (a generated program is printed for a rerun).
//   usage: program_cosim (--program FILE [--machine mill|lathe] [--start X,Y] | --random N [--blocks B])
//                        [--step MM] [--accel MM_PER_S2] [--rapid MM_PER_MIN] [--vmax MM_PER_MIN] [--min-speed
//                        MM_PER_MIN]
//                        [--default-feed MM_PER_MIN] [--clock HZ] [--timing A,B,C,D] [--pipelined]
//                        [--seed S] [--row]
// The machine is the default mill or lathe with the options' changes; the clock by
// default the slowest that follows the plan (speed::slowest_clock), 5% over.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <systemc>

#include "host/program_plan/program_plan.hpp"
#include "model/datapath/errors.hpp"
#include "tb/cosim/motion_cosim.hpp"
#include "tb/cosim/paced_program.hpp"
#include "tb/measure/pace_report.hpp"
#include "tb/random/random_program.hpp"

using namespace dda;

namespace {

struct Settings {
  program::ReadOptions read;
  program::LatticeOptions lattice;
  speed::MachineLimits lim;
  double clock = 0;
  motion::PacedRunOptions run;
  bool row = false;  // a table row instead of the sentence
};

// One program through the co-simulation; prints its line.
void run_one(motion::MotionCosim& h, std::istream& in, const std::string& name, const Settings& s) {
  const speed::PlannedProgram pp = speed::plan_program_pieces(in, name, s.read, s.lattice, s.lim);
  const speed::PlannerLimits pl = speed::planner_limits(s.lim, s.read.machine);
  const double step_mm = double(s.lattice.step) / double(program::kNmPerMm);
  // By default the slowest clock that follows the plan, 5% over, in whole kHz.
  const double clock = s.clock > 0 ? s.clock : std::ceil(speed::slowest_clock(pp, pl, step_mm) * 1.05 / 1000) * 1000;
  const speed::ProgramPacing pace = speed::program_pacing(pp, pl, s.lim, s.lattice.step, clock);
  const motion::MotionLimits pins = motion::pin_limits(pp, pl, s.lim, step_mm, clock);
  const motion::PacedRun r = motion::run_paced_program(h, pp, pace, pins, s.run);
  if (!(r.position == pp.plan.to)) {
    throw GuardError(fmt::format("{}: the block ends at ({}, {}, {}), the program at ({}, {}, {})", name, r.position.x,
                                 r.position.y, r.position.z, pp.plan.to.x, pp.plan.to.y, pp.plan.to.z));
  }
  // The pacer's reference model on the golden datapath at the same clock (the block's
  // pacer, without the bus): every cruise against the plan and every piece's end against
  // its exit speed, each a failure 1% over.
  const PaceResult ref = pace_program(pp, pace.setup, pl, s.lim);
  if (ref.worst_cruise_error >= 0.01) {
    throw GuardError(fmt::format("{}: the pacer cruises up to {:.4f} off the planned speeds (at most 0.01)", name,
                                 ref.worst_cruise_error));
  }
  if (ref.worst_junction_excess >= 0.01) {
    throw GuardError(fmt::format("{}: the pacer ends a piece up to {:.4f} over its exit speed (at most 0.01)", name,
                                 ref.worst_junction_excess));
  }
  const auto& m = r.monitor;
  const auto share = [&](double peak, double limit) { return limit > 0 ? fmt::format("{:.3f}", peak / limit) : "-"; };
  const auto axes = [&](const std::array<double, 3>& peak, const std::array<double, 3>& limit) {
    return fmt::format("X {} Y {} Z {}", share(peak[0], limit[0]), share(peak[1], limit[1]), share(peak[2], limit[2]));
  };
  const double seconds = double(r.cycles) / clock, planned = pp.totals.time - pp.totals.dwell;
  // The plan's profile on the DDA's path (its pieces' lengths, the drives starting and
  // stopping at VMIN), against the programmed path.
  const double on_dda = speed::entries_seconds(pace.entries, pace.setup);
  double programmed = 0;
  for (const speed::PlannedSegment& p : pp.segments) programmed += p.seg.length;
  const double dda_path = speed::entries_length(pace.entries, pace.setup) / programmed;
  if (s.row) {
    fmt::print("| {} | {} | {:.0f} | {} | {:.3f} | {:.3f} | {:.4f} | {:.3f} | {} | {} | {} | {} | {:.4f} | {:.4f} |\n",
               name, pp.plan.pieces.size(), clock, r.cycles, seconds, planned, dda_path, on_dda,
               share(m.peak_speed(), pins.max_speed), share(m.peak_accel(), pins.max_accel),
               axes(m.peak_axis_speed(), pins.axis_speed), axes(m.peak_axis_accel(), pins.axis_accel),
               ref.worst_cruise_error, ref.worst_junction_excess);
  } else {
    fmt::print(
        "program_cosim: {}: {} pieces, {} cycles at {:.0f} Hz ({:.3f} s; planned motion {:.3f} s; {:.3f} s on the "
        "DDA's path, {:.4f} of the programmed one, rests at VMIN), SystemC model, RTL and reference model equal at "
        "every edge, at its end point; at the RTL's pins (of the limits): path speed {}, "
        "acceleration {}; per axis speed {}, acceleration {}; the pacer cruising within {:.4f} of the planned speeds, "
        "ending its {} pieces at most {:.4f} over their exit speeds; 0 violations\n",
        name, pp.plan.pieces.size(), r.cycles, clock, seconds, planned, on_dda, dda_path,
        share(m.peak_speed(), pins.max_speed), share(m.peak_accel(), pins.max_accel),
        axes(m.peak_axis_speed(), pins.axis_speed), axes(m.peak_axis_accel(), pins.axis_accel), ref.worst_cruise_error,
        ref.junctions, ref.worst_junction_excess);
  }
  std::fflush(stdout);
}

motion::StageTimings parse_timing(const std::vector<std::uint32_t>& v) {
  if (v.empty()) return {};
  if (v.size() != 4) throw InputError("--timing takes STEPLEN,STEPSPACE,DIRSETUP,DIRHOLD");
  return {v[0], v[1], v[2], v[3]};
}

}  // namespace

int sc_main(int argc, char* argv[]) {
  CLI::App app{"part programs at their planned speeds: SystemC model and RTL co-simulated, speed monitor at the pins"};
  std::string file, machine = "mill", step = "0.01";
  std::vector<std::string> start;
  std::vector<std::uint32_t> timing;
  double accel = 0, clock = 0, default_feed = 0, rapid = 0, vmax = 0, min_speed = 0;
  int random = 0, blocks = 10;
  Settings s;
  app.add_option("--program", file, "the part program");
  app.add_option("--random", random, "N generated programs instead (lines, arcs and ellipses at random angles)")
      ->check(CLI::PositiveNumber);
  app.add_option("--blocks", blocks, "blocks of each generated program (default 10)")->check(CLI::PositiveNumber);
  app.add_option("--machine", machine, "mill (default) or lathe");
  app.add_option("--start", start, "the tool's start X,Y (lathe X,Z, X a diameter), mm")->delimiter(',')->expected(2);
  app.add_option("--step", step, "the lattice step, mm (default 0.01)");
  app.add_option("--accel", accel, "every axis' acceleration, mm/s^2 (default: the machine's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--default-feed", default_feed, "the feed of a program that gives no F, mm/min")
      ->check(CLI::PositiveNumber);
  app.add_option("--rapid", rapid, "the rapid rate, mm/min (default: the machine's)")->check(CLI::PositiveNumber);
  app.add_option("--min-speed", min_speed, "where a drive starts and stops, mm/min (default: the machine's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--vmax", vmax, "every axis' velocity, mm/min (default: the machine's)")->check(CLI::PositiveNumber);
  app.add_option("--clock", clock, "the block's clock, Hz (default: the slowest that follows the plan, 5% over)")
      ->check(CLI::PositiveNumber);
  app.add_option("--timing", timing, "every axis' STEPLEN,STEPSPACE,DIRSETUP,DIRHOLD, clocks")->delimiter(',');
  app.add_flag("--pipelined", s.run.pipelined, "pipelined Wishbone cycles (default classic)");
  app.add_option("--seed", s.run.seed, "the bus's seed, and the generated programs' (default 1)");
  app.add_flag("--row", s.row, "print each program's figures as a row of docs/results.md's table");
  CLI11_PARSE(app, argc, argv);
  std::string current = file;
  try {
    if (file.empty() == (random == 0)) throw InputError("give --program FILE or --random N");
    if (random > 0 && (!start.empty() || machine != "mill"))
      throw InputError("--random draws mill programs from the origin: leave --start and --machine out");
    if (random == 0 && app.count("--blocks") > 0) throw InputError("--blocks goes with --random");
    if (machine != "mill" && machine != "lathe") throw InputError("--machine is mill or lathe");
    s.read.machine = machine == "lathe" ? program::Machine::Lathe : program::Machine::Mill;
    if (!start.empty()) {
      const auto p = program::parse_mm(start[0]);
      const auto q = program::parse_mm(start[1]);
      if (!p || !q) throw InputError("--start: two decimal millimetres");
      s.read.start = program::start_point(s.read.machine, *p, *q);
    }
    s.lattice.step = program::parse_step(step);
    s.lim = speed::default_limits(s.read.machine);
    if (accel > 0)
      for (speed::AxisLimits& a : s.lim.axes) a.accel = accel;
    if (default_feed > 0) s.lim.default_feed = default_feed;
    if (rapid > 0) s.lim.rapid = rapid;
    if (min_speed > 0) s.lim.min_speed = min_speed;
    if (vmax > 0)
      for (speed::AxisLimits& a : s.lim.axes) a.vmax = vmax;
    s.clock = clock;
    s.run.timing = parse_timing(timing);
    motion::MotionCosim h;
    if (!file.empty()) {
      std::ifstream in(file);
      if (!in) throw InputError("cannot open " + file);
      run_one(h, in, file, s);
      return 0;
    }
    std::mt19937_64 rng(s.run.seed);
    for (int k = 0; k < random; ++k) {
      const randgen::RandomProgram p = randgen::random_program(rng, blocks, k % 2 == 0);
      current = p.text;
      std::istringstream in(p.text);
      run_one(h, in, fmt::format("random program {} of seed {}", k, s.run.seed), s);
    }
  } catch (const std::exception& e) {
    std::cerr << "program_cosim: " << e.what() << '\n';
    if (random > 0 && !current.empty()) std::cerr << "the program:\n" << current;
    return 1;
  }
  return 0;
}
