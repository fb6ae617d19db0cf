// SPDX-License-Identifier: Apache-2.0
// dda vectors: test vectors computed by the golden model (never by running the RTL).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "accuracy/golden.hpp"
#include "datapath/hw_params.hpp"
#include "motion/motion_model.hpp"
#include "vector_set.hpp"

namespace CLI {
class App;
}

namespace dda::vec {

struct Options {
  std::string out_dir;
  std::string command_line;                     // the exact dda command, recorded in the manifest
  std::uint64_t seed = 1;                       // the ce pattern's seed
  int ce_percent = 100;                         // chance (percent) that ce_i is high on a cycle
  std::uint64_t max_size = kDefaultMaxSetSize;  // bytes: a larger set is refused before it is written
};

// Writes the vector set of `plans` run back to back into opt.out_dir (atomically: a
// temporary directory renamed into place). docs/vectors.md describes the files.
void write_vector_set(const std::vector<Plan>& plans, const Options& opt);

// dda vectors --bus: the motion block's per-cycle set (cli/bus_vectors.cpp).
struct BusOptions {
  bool pipelined = false;  // Wishbone cycles: classic or pipelined
  int idle_percent = 20;   // chance of an idle cycle before each request (seeded)
  int abort_after = 0;     // > 0: abort that many cycles after the last commit
  std::string vcd;         // non-empty: also run the RTL through the same cycles, this waveform
  motion::StageTimings timing_x, timing_y, timing_z;  // the step/dir stages' timings (cycles)
  std::uint32_t polarity = 0;                         // POLARITY
  std::uint32_t feed = 0;                             // every piece's feed increment (0: full rate) ...
  double feed_rate = 0, clock_hz = 0;                 // ... or each piece's for this feed (steps/s) and clock
};
// The --bus options of `dda vectors` as given, and their checked values (InputError for
// a malformed timing, a feed without --bus, ...).
struct BusCli {
  bool bus = false, pipelined = false;
  int abort_after = 0;
  std::string timing, timing_x, timing_y, timing_z;
  std::uint32_t polarity = 0, feed = 0;
  double feed_rate = 0, clock_hz = 0;
};
void add_bus_options(CLI::App* vectors, BusCli& c);
BusOptions bus_options(const BusCli& c);
void write_bus_vector_set(const std::vector<Plan>& plans, const Options& opt, const BusOptions& bus);
// The bus bench's field table (tb/hdl/dda_bus_vec_fields.vh).
std::string bus_verilog_fields();

// A Verilog macro NAME(cyc, exp, got) that prints the first field (most significant
// first, name and width) where the expected and the sampled words differ.
std::string report_macro(const std::string& macro, const std::vector<std::pair<std::string, int>>& fields);

// The bench's field table (tb/hdl/dda_vec_fields.vh), generated from the register table.
std::string verilog_fields(const hw::SignalTable& t = hw::signal_table());

}  // namespace dda::vec
