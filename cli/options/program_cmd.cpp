// SPDX-License-Identifier: Apache-2.0
// `--program FILE`: the options of a part program's run.
#include "cli/options/program_cmd.hpp"

#include <CLI/CLI.hpp>
#include <optional>
#include <utility>

#include "cli/options/arc_options.hpp"
#include "host/program/program.hpp"

namespace dda::cli {

using program::Length;
using program::ProgramPlan;

namespace {

// "X,Y" in millimetres (decimal, up to 6 decimals) to nanometres.
std::pair<Length, Length> parse_mm_pair(const std::string& name, const std::string& s) {
  const auto comma = s.find(',');
  const std::optional<Length> p = comma == std::string::npos ? std::nullopt : program::parse_mm(s.substr(0, comma));
  const std::optional<Length> q = comma == std::string::npos ? std::nullopt : program::parse_mm(s.substr(comma + 1));
  if (!p || !q) {
    throw InputError(name + " = '" + s + "' is invalid: give X,Y in millimetres (e.g. 10,-2.5; up to 6 decimals)");
  }
  return {*p, *q};
}

}  // namespace

void add_program_options(CLI::App* sub, ProgramCli& o) {
  sub->add_option("--program", o.file,
                  "run a part program (G-code, docs/programs.md; - for standard input) instead of one arc");
  sub->add_option("--machine", o.machine,
                  "with --program: mill (default; G17, X and Y as given) or lathe (G18: Z along the spindle as "
                  "x, X as a diameter, its radius as y)");
  sub->add_option("--start", o.start,
                  "with --program: the tool's start in millimetres, mill X,Y or lathe X,Z (X a diameter; "
                  "default 0,0)");
  sub->add_option("--step", o.step, "with --program: the lattice unit in millimetres (default 0.001)");
  sub->add_option("--dialect", o.dialect,
                  "with --program: linuxcnc, hnc or fanuc (default: detected from the program; docs/programs.md)");
  sub->add_flag("--block-delete", o.block_delete, "with --program: skip the blocks that start with '/'");
  sub->add_option("--subroutine-path", o.subroutine_path,
                  "with --program: folders where LinuxCNC's o<name> call finds name.ngc after the program's "
                  "own (LinuxCNC's SUBROUTINE_PATH; colon-separated, or the option given again)")
      ->delimiter(':');
}

std::string program_name(const ProgramCli& o) { return o.file == "-" ? "<stdin>" : o.file; }

ProgramRun program_run(const ProgramCli& o, Preload preload, bool hardware) {
  ProgramRun run;
  run.file = program_name(o);
  run.hardware = hardware;
  if (o.machine == "lathe") {
    run.read.machine = program::Machine::Lathe;
  } else if (o.machine != "mill") {
    throw InputError("machine = '" + o.machine + "' is invalid: use mill or lathe");
  }
  if (!o.dialect.empty()) {
    if (o.dialect == "linuxcnc") {
      run.read.dialect = program::Dialect::LinuxCnc;
    } else if (o.dialect == "hnc") {
      run.read.dialect = program::Dialect::Hnc;
    } else if (o.dialect == "fanuc") {
      run.read.dialect = program::Dialect::Fanuc;
    } else {
      throw InputError("dialect = '" + o.dialect + "' is invalid: use linuxcnc, hnc or fanuc");
    }
  }
  run.read.block_delete = o.block_delete;
  run.read.subroutine_path = o.subroutine_path;
  if (!o.start.empty()) {
    const auto [p, q] = parse_mm_pair("start", o.start);
    run.read.start = program::start_point(run.read.machine, p, q);
  }
  run.lattice.step = program::parse_step(o.step);
  run.lattice.preload = preload;
  return run;
}

ProgramPlan load_program(const ProgramCli& o, Preload preload, bool hardware) {
  const ProgramRun run = program_run(o, preload, hardware);
  const auto in = program::open_program(o.file);
  program::Program prog;
  const program::ReadSummary rs =
      program::read_stream(*in, run.file, run.read, [&](const program::Move& mv) { prog.moves.push_back(mv); });
  prog.start = rs.start;
  ProgramPlan pp = program::plan_program(prog, run.lattice, run.file);
  if (hardware) program::check_hardware(pp, run.file);
  return pp;
}

ProgramCli program_from_args(const std::vector<std::string>& args) {
  CLI::App app{"dda program options"};
  ProgramCli o;
  add_program_options(&app, o);
  parse_args(app, args);
  if (!o.given()) throw InputError("--program FILE is required");
  return o;
}

}  // namespace dda::cli
