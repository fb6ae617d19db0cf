// SPDX-License-Identifier: Apache-2.0
// dda entries: the block-entry words a host writes for each piece of an arc, a line or a
// part program (host/run/entries.hpp; docs/design.md, "The command queue").
#pragma once

#include <string>

#include "cli/options/arc_options.hpp"

namespace CLI {
class App;
}

namespace dda::cli {

struct EntriesCli {
  ArcOptions arc;
  std::string machine_config;
  double clock_hz = 0;
};

void add_entries_options(CLI::App* sub, EntriesCli& e);
void run_entries(const EntriesCli& e);

}  // namespace dda::cli
