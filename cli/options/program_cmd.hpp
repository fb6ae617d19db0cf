// SPDX-License-Identifier: Apache-2.0
// `--program FILE` on the `dda` subcommands (docs/programs.md): its options and what
// they make of the program's run.
#pragma once

#include <string>

#include <string>
#include <vector>
#include "host/accuracy/golden.hpp"
#include "host/pipeline/pipeline.hpp"

#include "host/program_plan/program_plan.hpp"

namespace CLI {
class App;
}

namespace dda::cli {

struct ProgramCli {
  std::string file;  // "-": standard input; empty: no program
  std::string machine = "mill", start, step = "0.001", dialect;
  bool block_delete = false;
  std::vector<std::string> subroutine_path;
  bool given() const { return !file.empty(); }
};
void add_program_options(CLI::App* sub, ProgramCli& o);

// The program's name in messages: the path, or "<stdin>".
std::string program_name(const ProgramCli& o);

// The program's run as the options give it (reader, lattice, window); InputError for
// a bad option.
ProgramRun program_run(const ProgramCli& o, Preload preload, bool hardware);

// The program options written as for the `dda` command ({"--program", "FILE",
// "--machine", "lathe", ...}); InputError for a bad one or without --program.
ProgramCli program_from_args(const std::vector<std::string>& args);

// Reads and plans the whole program (vector sets); with `hardware` (engines systemc
// and rtl) also refuses a block whose commands the hardware's widths cannot hold.
// Throws ProgramError ("FILE:LINE:COLUMN: message") or InputError for a bad option.
program::ProgramPlan load_program(const ProgramCli& o, Preload preload, bool hardware);

}  // namespace dda::cli
