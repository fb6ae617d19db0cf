// SPDX-License-Identifier: Apache-2.0
// dda blocks: the motion blocks the reader makes of a part program, in machine
// coordinates, before any lattice (docs/programs.md, "What a program reads as"): what
// to compare with another interpreter (scripts/rs274-compare.py compares LinuxCNC's).
#pragma once

#include <string>

#include "cli/options/program_cmd.hpp"

namespace CLI {
class App;
}

namespace dda::cli {

struct BlocksCli {
  ProgramCli prog;
  std::string format = "text", out;
};

void add_blocks_options(CLI::App* sub, BlocksCli& b);
void run_blocks(const BlocksCli& b);

}  // namespace dda::cli
