// SPDX-License-Identifier: Apache-2.0
#include "cli/entries/entries_cmd.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/options/output.hpp"
#include "host/program/program.hpp"
#include "host/run/entries.hpp"
#include "host/run/live_run.hpp"
#include "model/motion/motion_map.hpp"

namespace dda::cli {

void add_entries_options(CLI::App* sub, EntriesCli& e) {
  ArcUses uses;
  uses.engine = uses.vcd = false;
  add_arc_options(sub, e.arc, "text or json", "text", uses);
  sub->add_option("--machine-config", e.machine_config,
                  "with --program: the machine (JSON, docs/programs.md): its limits, steps per mm and clock");
  sub->add_option("--clock", e.clock_hz,
                  "with --program: the block's clock, Hz, the pacing fields are counted in (default: the machine "
                  "config's clock_hz, 30e6)");
  sub->footer(
      "Each piece's 27 words, word 0 first: the host writes word k to ENTRY + 4k (0x100 + 4k), then CTRL.commit "
      "(docs/design.md, \"The command queue\"). An arc or a line runs at the core's full rate (feed increment 0, no "
      "pacing); a program's pieces carry their planned speeds, as dda run writes them, after a first line (JSON: "
      "the keys accel and vmin) giving the ACCEL and VMIN the host writes before them.");
}

void run_entries(const EntriesCli& e) {
  const ArcOptions& o = e.arc;
  check_program_options(o);
  const bool json = parse_enum<bool>("format", o.format.empty() ? "text" : o.format, {{"text", false}, {"json", true}});
  const auto given = [&](double v) { return v != 0; };
  if (!o.prog.given() && (!e.machine_config.empty() || given(e.clock_hz)))
    throw InputError("--machine-config and --clock go with --program (an arc's entries are not paced)");
  Output out(o.out);
  std::ostream& os = out.stream();
  // (JSON written a piece at a time: memory bounded at any program length.)
  bool first = true;
  const auto put = [&](const live::PieceEntry& p) {
    if (json) {
      const nlohmann::json j = {{"piece", p.piece},
                                {"line", p.line},
                                {"from", {p.from.x, p.from.y, p.from.z}},
                                {"to", {p.to.x, p.to.y, p.to.z}},
                                {"words", p.words}};
      os << (first ? "\n" : ",\n") << j.dump();
      first = false;
      return;
    }
    os << fmt::format("piece {}", p.piece) << (p.line ? fmt::format(" line {}", p.line) : "")
       << fmt::format(" from {},{},{} to {},{},{}:", p.from.x, p.from.y, p.from.z, p.to.x, p.to.y, p.to.z);
    for (const std::uint32_t w : p.words) os << fmt::format(" {:08x}", w);
    os << '\n';
  };
  if (o.prog.given()) {
    const ProgramRun run = program_run(o.prog, parse_preload(o.preload), true);
    speed::MachineLimits lim = speed::default_limits(run.read.machine);
    if (!e.machine_config.empty()) lim = speed::read_machine_config(e.machine_config, lim, run.read.machine);
    speed::check(lim, run.read.machine);
    ProgramRun r = run;
    r.lattice.step = live::live_step(lim, run.read.machine, run.lattice.step);
    double clock = lim.live.clock_hz;
    if (given(e.clock_hz)) {
      if (!(std::isfinite(e.clock_hz) && e.clock_hz > 0 && e.clock_hz <= 1e9))
        throw InputError(fmt::format("--clock = {} is out of range: Hz, above 0 and at most 1e9", e.clock_hz));
      clock = e.clock_hz;
    }
    const speed::PaceSetup setup = live::program_setup(r, lim, clock);
    // The block's settings the entries are paced for: written before them.
    if (json) {
      os << fmt::format("{{\"accel\": {}, \"vmin\": {}, \"clock_hz\": {}, \"step_mm\": {}, \"pieces\": [", setup.accel,
                        setup.vmin, setup.clock_hz, setup.step_mm);
    } else {
      os << fmt::format("# ACCEL {} VMIN {} (the block at {} Hz, a step of {} mm)\n", setup.accel, setup.vmin,
                        setup.clock_hz, setup.step_mm);
    }
    const auto in = program::open_program(o.prog.file);
    live::program_entries(*in, r, lim, setup, put);
  } else {
    if (json) os << "{\"accel\": null, \"vmin\": null, \"clock_hz\": null, \"step_mm\": null, \"pieces\": [";
    for (const live::PieceEntry& p : live::plan_entries(make_plan(o))) put(p);
  }
  if (json) os << "\n]}\n";
  out.commit();
}

}  // namespace dda::cli
