// SPDX-License-Identifier: Apache-2.0
// `--program FILE` on the `dda` subcommands (docs/programs.md): reading, planning and
// the per-block reports of a part program.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "dda/golden.hpp"
#include "dda/program_plan.hpp"

namespace CLI {
class App;
}

namespace dda::cli {

struct ProgramCli {
  std::string file;  // "-": standard input; empty: no program
  std::string machine = "mill", start, step = "0.001";
  bool given() const { return !file.empty(); }
};
void add_program_options(CLI::App* sub, ProgramCli& o);

// The program's name in messages: the path, or "<stdin>".
std::string program_name(const ProgramCli& o);

// Reads and plans the program; with `hardware` (engines systemc and rtl) also refuses a
// block whose commands the hardware's widths cannot hold. Throws ProgramError
// ("FILE:LINE:COLUMN: message") or InputError for a bad option.
program::ProgramPlan load_program(const ProgramCli& o, Preload preload, bool hardware);

// One row per motion block (source line, block number, kind, programmed end in mm, its
// lattice point and rounding, commands, steps, iterations, largest and mean distance
// from the programmed geometry) and the totals.
enum class BlockStatsFormat { Text, Csv, Json };
void write_program_stats(std::ostream& os, const program::ProgramPlan& pp, const std::vector<Iteration>& iters,
                         BlockStatsFormat fmt);

// The whole path over the programmed geometry (dda plot --program).
void write_program_svg(std::ostream& os, const program::ProgramPlan& pp, const std::vector<Iteration>& iters,
                       const std::string& title);

}  // namespace dda::cli
