// SPDX-License-Identifier: Apache-2.0
#include "cli/vectors_cmd.hpp"

#include <CLI/CLI.hpp>
#include <utility>

#include "cli/options/output.hpp"
#include "host/speed/pace_plan.hpp"
#include "model/datapath/hw_command.hpp"

namespace dda::cli {

namespace {

// The vector set's options: the seed and ce pattern checked, and the command line as
// given (for the manifest; an argument with a space quoted).
vec::Options vector_options(const VectorsCli& v, int argc, char** argv) {
  vec::Options vo;
  vo.out_dir = v.out_dir;
  vo.seed = std::uint64_t(parse_int_in("seed", v.seed, 0, std::numeric_limits<std::int64_t>::max()));
  vo.ce_percent = int(parse_int_in("ce-percent", v.ce_percent, 1, 100));
  vo.max_size = vec::parse_size("max-size", v.max_size);
  vo.command_line = "dda";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    vo.command_line += a.find(' ') == std::string::npos ? " " + a : " \"" + a + "\"";
  }
  return vo;
}

// The plans of the vector set: the arc (or program) given, then each --then arc.
std::vector<Plan> vector_plans(const VectorsCli& v) {
  std::vector<Plan> plans{make_plan(v.arc)};
  if (v.arc.prog.given() && !v.then.empty())
    throw InputError("--then is invalid with --program: one program is one run");
  for (const std::string& then : v.then) {
    CLI::App sub{"arc"};
    ArcOptions o;
    add_arc_options(&sub, o, "", "", ArcUses{false, false, false, false, false});
    try {
      sub.parse(then, false);
    } catch (const CLI::ParseError& e) {
      throw InputError("then = '" + then + "' is invalid: " + e.what());
    }
    plans.push_back(make_plan(o));
  }
  return plans;
}

// dda vectors --bus --program FILE --speeds --clock HZ: the program's pieces (cut where
// the planner cuts them) with the entries of its plan.
void run_planned_vectors(const VectorsCli& v, const vec::Options& vo) {
  if (!v.arc.prog.given() || !v.bus.bus)
    throw InputError("--speeds and the machine's limits go with --bus --program: the block paces the plan");
  if (!v.then.empty()) throw InputError("--then is invalid with --program: one program is one run");
  check_program_options(v.arc);
  vec::BusCli bc = v.bus;
  bc.planned = true;
  vec::BusOptions bo = vec::bus_options(bc);
  const ProgramRun run = program_run(v.arc.prog, parse_preload(v.arc.preload), true);
  speed::MachineLimits lim = machine_limits(v.speed, run.read.machine);
  if (v.bus.accel_opt && v.bus.accel_opt->count()) {
    for (speed::AxisLimits& a : lim.axes) a.accel = positive("accel", v.bus.accel);
  }
  const auto in = program::open_program(v.arc.prog.file);
  const speed::PlannedProgram pp = speed::plan_program_pieces(*in, run.file, run.read, run.lattice, lim);
  for (const Piece& pc : pp.plan.pieces) hw::pack_command(pc.cmd);  // (refused if too wide for the hardware)
  const speed::PlannerLimits pl = speed::planner_limits(lim, run.read.machine);
  speed::ProgramPacing pace = speed::program_pacing(pp, pl, lim, run.lattice.step, bo.clock_hz);
  bo.planned_accel = pace.setup.accel;
  bo.planned_vmin = pace.setup.vmin;
  bo.planned_entries = std::move(pace.entries);
  AtomicFile wave(v.arc.vcd);
  bo.vcd = wave.write_path();
  vec::write_bus_vector_set({pp.plan}, vo, bo);
  wave.commit();
}

}  // namespace

void add_vectors_options(CLI::App* sub, VectorsCli& v) {
  ArcUses uses;
  uses.engine = uses.out = false;  // the golden model's, into --out-dir
  uses.vcd_help = "with --bus: the RTL's waveform through the same cycles, into FILE";
  add_arc_options(sub, v.arc, "hex (with CSV and a JSON manifest)", "hex", uses);
  sub->add_option("--out-dir", v.out_dir, "directory of the vector set (written atomically)");
  sub->add_option("--then", v.then, "\"ARC OPTIONS\" of a further arc run back to back (repeatable)");
  sub->add_option("--seed", v.seed, "seed of the ce pattern (default 1)");
  sub->add_option("--ce-percent", v.ce_percent, "chance in percent that ce_i is high on a cycle (default 100)");
  sub->add_option("--max-size", v.max_size,
                  "refuse a set larger than SIZE bytes (K, M, G, T: binary multiples; default 1G), before it is "
                  "written");
  vec::add_bus_options(sub, v.bus);
  add_speed_options(sub, v.speed, false, true);
}

void run_vectors(const VectorsCli& v, int argc, char** argv) {
  parse_enum<int>("format", v.arc.format, {{"hex", 0}});
  if (v.out_dir.empty()) throw InputError("vectors needs --out-dir DIR");
  if (!v.arc.vcd.empty() && !v.bus.bus) {
    throw InputError("--vcd goes with --bus in vectors: the RTL's waveform of the bus-level set");
  }
  const vec::Options vo = vector_options(v, argc, argv);
  if (v.speed.wanted()) return run_planned_vectors(v, vo);
  if (!v.bus.io_scenario.empty()) {
    if (!v.bus.bus) throw InputError("--io-scenario goes with --bus");
    if (!v.arc.a.empty() || !v.arc.b.empty() || v.arc.line || !v.then.empty() || !v.arc.prog.file.empty())
      throw InputError("--io-scenario runs its own moves: give no arc, --line, --then or --program");
  }
  const std::vector<Plan> plans = v.bus.io_scenario.empty() ? vector_plans(v) : std::vector<Plan>{};
  if (v.bus.bus) {
    vec::BusOptions bo = vec::bus_options(v.bus);
    AtomicFile wave(v.arc.vcd);  // the RTL run beside the set: written only on success
    bo.vcd = wave.write_path();
    vec::write_bus_vector_set(plans, vo, bo);
    wave.commit();
  } else {
    vec::bus_options(v.bus);  // refuses the bus options without --bus
    vec::write_vector_set(plans, vo);
  }
}

}  // namespace dda::cli
