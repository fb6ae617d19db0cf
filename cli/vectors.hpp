// SPDX-License-Identifier: Apache-2.0
// dda vectors: test vectors computed by the golden model (never by running the RTL).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dda/golden.hpp"
#include "dda/hw_params.hpp"

namespace dda::vec {

struct Options {
  std::string out_dir;
  std::string command_line;  // the exact dda command, recorded in the manifest
  std::uint64_t seed = 1;    // the ce pattern's seed
  int ce_percent = 100;      // chance (percent) that ce_i is high on a cycle
};

// Writes the vector set of `plans` run back to back into opt.out_dir (atomically: a
// temporary directory renamed into place). docs/vectors.md describes the files.
void write_vector_set(const std::vector<Plan>& plans, const Options& opt);

// The bench's field table (tb/hdl/dda_vec_fields.vh), generated from the register table.
std::string verilog_fields(const hw::SignalTable& t = hw::signal_table());

}  // namespace dda::vec
