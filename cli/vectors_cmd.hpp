// SPDX-License-Identifier: Apache-2.0
// `dda vectors`: its options (the arc's or the program's, the set's, the bus's, the
// planned speeds') and the run that writes a vector set (docs/vectors.md).
#pragma once

#include <string>
#include <vector>

#include "cli/options/arc_options.hpp"
#include "cli/speed_cmd.hpp"
#include "cli/vectors.hpp"

namespace CLI {
class App;
}

namespace dda::cli {

// The options of `dda vectors` besides the arc's.
struct VectorsCli {
  ArcOptions arc;
  std::string out_dir, seed = "1", ce_percent = "100", max_size = "1G";
  std::vector<std::string> then;  // further arcs, each its options in one string
  vec::BusCli bus;
  SpeedCli speed;  // --program --speeds: the bus set at the planned speeds
};

void add_vectors_options(CLI::App* sub, VectorsCli& v);
// Writes the set the options ask for (InputError for options that do not go together).
void run_vectors(const VectorsCli& v, int argc, char** argv);

}  // namespace dda::cli
