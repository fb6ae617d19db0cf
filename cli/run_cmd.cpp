// SPDX-License-Identifier: Apache-2.0
#include "cli/run_cmd.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <sstream>

#include "host/program_plan/program_plan.hpp"
#include "host/run/controls.hpp"
#include "host/run/live_run.hpp"
#include "model/datapath/errors.hpp"
#include "model/datapath/hw_command.hpp"
#include "tb/engines/sim_port.hpp"

namespace dda::cli {

void add_run_options(CLI::App* sub, RunCli& r) {
  sub->add_option("program", r.prog.file, "the part program (G-code, docs/programs.md; - for standard input)")
      ->required();
  sub->add_option("--port", r.port,
                  "where the block is: sim (its RTL verilated here, behind its SPI bridge, with a simulated "
                  "machine), with options sim:KEY=VALUE,...: estop=S (the E-stop pressed at S seconds), "
                  "pause=PCT and pause-ms=MS (the host pauses before PCT% of its frames, up to MS each), "
                  "host-dies=S (the host stops writing at S seconds), seed=N. Default: the machine config's \"port\"");
  sub->add_option("--machine-config", r.machine_config,
                  "the machine (JSON, docs/programs.md): its limits, and for a live run the drives' steps per mm, "
                  "step/dir timings and polarity, the inputs, the block's clock, the watchdog and the port");
  sub->add_option("--machine", r.prog.machine, "mill (default) or lathe (X a diameter in the program)");
  sub->add_option("--start", r.prog.start, "the tool's start in millimetres, mill X,Y or lathe X,Z (default 0,0)");
  r.step_opt = sub->add_option("--step", r.prog.step,
                               "the lattice unit in millimetres (default: 1 / the drives' steps_per_mm, else 0.001)");
  sub->add_option("--dialect", r.prog.dialect, "linuxcnc, hnc or fanuc (default: detected)");
  sub->add_flag("--block-delete", r.prog.block_delete, "skip the blocks that start with '/'");
  sub->add_option("--subroutine-path", r.prog.subroutine_path, "folders where o<name> call finds name.ngc")
      ->delimiter(':');
  sub->add_option("--status-every", r.status_every,
                  "a status line every SECONDS of the machine's time (the sim port's: simulated), each on its own "
                  "line; without it, on a terminal, one line refreshed in place")
      ->check(CLI::PositiveNumber);
  sub->add_option("--control", r.control,
                  "a control file (or FIFO) read as it grows: lines '[@SECONDS] hold|resume|override "
                  "PERCENT|+|-|stop|hard-stop'");
  sub->add_option("--vcd", r.vcd, "with --port sim: the block's waveform");
  sub->add_flag("--quiet", r.quiet, "no status lines");
  sub->footer(std::string("On a terminal, ") + live::TerminalControls::keys() +
              ". Without one: SIGINT or SIGTERM a soft stop (twice: a hard stop), SIGUSR1 a feed hold, SIGUSR2 its "
              "end, or --control FILE.\n\nExit status:\n" +
              live::exit_table());
}

namespace {

// sim[:key=value,...]
motion::SimPortOptions sim_options(const std::string& port) {
  motion::SimPortOptions o;
  if (port == "sim") return o;
  if (port.rfind("sim:", 0) != 0)
    throw InputError("port = '" + port + "' is invalid: the ports are sim and sim:KEY=VALUE,... (dda run --help)");
  std::istringstream in(port.substr(4));
  std::string kv;
  while (std::getline(in, kv, ',')) {
    const auto eq = kv.find('=');
    const std::string key = kv.substr(0, eq), value = eq == std::string::npos ? "" : kv.substr(eq + 1);
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (eq == std::string::npos || value.empty() || *end != '\0' || !std::isfinite(v) || v < 0)
      throw InputError("port sim: '" + kv + "' is not KEY=VALUE with a number of 0 or more");
    if (key == "estop") {
      o.estop_at = v;
    } else if (key == "pause") {
      if (v > 100) throw InputError("port sim: pause is a percent of the frames, 0 to 100");
      o.pause_percent = v;
    } else if (key == "pause-ms") {
      o.pause_ms = v;
    } else if (key == "host-dies") {
      o.host_dies_at = v;
    } else if (key == "seed") {
      o.seed = std::uint64_t(v);
    } else {
      throw InputError("port sim: '" + key + "' is not a key (estop, pause, pause-ms, host-dies, seed)");
    }
  }
  if (o.pause_percent > 0 && o.pause_ms <= 0) throw InputError("port sim: pause needs pause-ms");
  return o;
}

// The simulated machine's limit switches in the block's axes (steps).
motion::MachineSwitches sim_switches(const speed::MachineLimits& lim, int plane, double step_mm) {
  motion::MachineSwitches sw;
  const std::array<std::size_t, 3> m = speed::machine_axes(plane);
  for (std::size_t a = 0; a < 3; ++a) {
    const speed::AxisDrive& d = lim.live.axes[m[a]];
    if (d.limit_neg_mm) sw.limit_neg[a] = std::llround(*d.limit_neg_mm / step_mm);
    if (d.limit_pos_mm) sw.limit_pos[a] = std::llround(*d.limit_pos_mm / step_mm);
  }
  return sw;
}

// What the run needs before it starts: the program's run, the machine, the port's
// options and the run's, the program file planned whole once.
struct Prepared {
  ProgramRun run;
  speed::MachineLimits lim;
  motion::SimPortOptions port;
  live::LiveOptions opt;
  double step_mm = 0;
};

Prepared prepare(const RunCli& r) {
  Prepared p;
  p.run = program_run(r.prog, Preload::Half, true);
  const program::Machine machine = p.run.read.machine;
  p.lim = speed::default_limits(machine);
  if (!r.machine_config.empty()) p.lim = speed::read_machine_config(r.machine_config, p.lim, machine);
  speed::check(p.lim, machine);
  // The lattice: the drives' steps per mm, unless --step gives it (then they agree).
  const program::Length step = live::live_step(p.lim, machine, p.run.lattice.step);
  if (step != p.run.lattice.step && r.step_opt && r.step_opt->count() > 0)
    throw InputError(fmt::format("--step {} and the drives' steps per mm (a step of {} mm) disagree", r.prog.step,
                                 double(step) / double(program::kNmPerMm)));
  p.run.lattice.step = step;
  p.step_mm = double(step) / double(program::kNmPerMm);
  const std::string port = r.port.empty() ? p.lim.live.port : r.port;
  if (port.empty()) throw InputError("give --port (sim; or the machine config's \"port\")");
  p.port = sim_options(port);
  p.port.clock_hz = p.lim.live.clock_hz;
  p.port.vcd = r.vcd;

  // A first pass over a program file: the whole plan checked (the reader, the planners,
  // the clock, the hardware's widths) before anything moves, and its totals for the
  // progress. (Standard input is read once: it is checked as it runs.)
  // (A lathe runs in G18; a program read once from standard input is taken in its
  // machine's plane.)
  int plane = machine == program::Machine::Lathe ? 180 : 170;
  Point start = program::on_lattice(p.run.read.start.value_or(program::Point2{}), step);
  const speed::PlannerLimits plim = speed::planner_limits(p.lim, machine);
  const speed::PaceSetup pace = speed::pace_setup(plim, p.lim, step, p.lim.live.clock_hz);
  if (r.prog.file != "-") {
    bool first = true;
    const auto in = program::open_program(r.prog.file);
    p.opt.totals = speed::stream_program_entries(*in, p.run.file, p.run.read, p.run.lattice, p.run.window, p.lim, pace,
                                                 [&](const speed::StreamEntry& e) {
                                                   hw::pack_command(e.piece.cmd);
                                                   if (first) {
                                                     plane = e.plane;
                                                     start = e.piece.from;
                                                     first = false;
                                                   }
                                                 });
  }
  p.port.start = start;
  p.port.accel_steps = plim.accel / p.step_mm;
  p.port.switches = sim_switches(p.lim, plane, p.step_mm);
  p.opt.status_every = r.quiet ? 0 : r.status_every > 0 ? r.status_every : isatty(STDOUT_FILENO) ? 0.2 : 0;
  p.opt.status_line = r.status_every <= 0 && isatty(STDOUT_FILENO);
  return p;
}

// The host made to die on the sim port: what the block did alone, from its registers.
void host_died(const motion::SimPort& sim, double clock_hz, live::LiveResult& res) {
  const motion::MotionModel& m = sim.model();
  const std::uint32_t st = m.read(motion::reg_offset("STATUS"));
  res.position =
      Point{std::int32_t(m.read(motion::reg_offset("POS_X"))), std::int32_t(m.read(motion::reg_offset("POS_Y"))),
            std::int32_t(m.read(motion::reg_offset("POS_Z")))};
  res.seconds = double(sim.clocks()) / clock_hz;
  if (motion::get_field("STATUS", "err_watchdog", st)) {
    res.exit = live::kWatchdog;
    res.message += ": the block's watchdog ran out and it came to rest";
  } else {
    res.message += fmt::format(": the block did not report its watchdog (STATUS 0x{:08X})", st);
  }
}

}  // namespace

void run_run(const RunCli& r) {
  const Prepared p = prepare(r);
  live::AllControls controls;
  controls.add(std::make_unique<live::SignalControls>());
  if (isatty(STDIN_FILENO) && r.prog.file != "-") controls.add(std::make_unique<live::TerminalControls>(STDIN_FILENO));
  if (!r.control.empty()) controls.add(std::make_unique<live::ControlFile>(r.control));

  motion::SimPort sim(p.port);
  const auto in = program::open_program(r.prog.file);
  live::LiveResult res = live::run_live(*in, p.run, p.lim, sim, controls, std::cout, p.opt);
  if (p.port.host_dies_at >= 0 && res.exit == live::kFailure && sim.host_died()) host_died(sim, p.port.clock_hz, res);
  bool agree = true;
  const std::string pins = sim.pins_report(res.position, agree);
  if (res.position_known || (p.port.host_dies_at >= 0 && sim.host_died())) {
    std::cout << fmt::format("position: {} ({} {} {} steps)\n",
                             live::position_mm(res.position, res.plane, p.step_mm, p.run.read.machine, res.axes),
                             res.position.x, res.position.y, res.position.z);
  } else {
    std::cout << "position: not read back (the block could not be reached)\n";
  }
  if (!pins.empty()) std::cout << pins << '\n';
  std::cout << fmt::format("time: {:.3f} s of the machine's, {} entries\n", res.seconds, res.entries);
  if (res.exit == live::kDone && !agree) {
    res.exit = live::kFailure;
    res.message = "the steps at the pins differ from the block's position registers";
  }
  std::cout.flush();
  if (res.exit != live::kDone) {
    std::cerr << "dda: stop: " << res.message << '\n';
    throw ExitStatus(res.exit);
  }
}

}  // namespace dda::cli
