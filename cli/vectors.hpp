// SPDX-License-Identifier: Apache-2.0
// dda vectors: test vectors computed by the golden model (never by running the RTL).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cli/vector_set.hpp"
#include "host/accuracy/golden.hpp"
#include "host/driver/motion_driver.hpp"
#include "model/datapath/hw_params.hpp"
#include "model/motion/motion_model.hpp"
#include "tb/measure/pace_report.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

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
  motion::Bus bridge = motion::Bus::wishbone;  // the block's own bus, or behind a bridge
  motion::Build build;                         // the block's build (docs/design.md, "Builds")
  bool pipelined = false;                      // Wishbone cycles: classic or pipelined
  int idle_percent = 20;                       // chance of an idle cycle before each request (seeded)
  int abort_after = 0;                         // > 0: abort that many cycles after the last commit
  std::string vcd;                             // non-empty: also run the RTL through the same cycles, this waveform
  std::string io_scenario;  // non-empty: this machine-input scenario (motion::kIoScenarios), not the plans
  motion::StageTimings timing_x, timing_y, timing_z;  // the step/dir stages' timings (cycles)
  std::uint32_t polarity = 0;                         // POLARITY
  std::uint32_t feed = 0;                             // every piece's feed increment (0: full rate) ...
  double feed_rate = 0, clock_hz = 0;                 // ... or each piece's for this feed (steps/s) and clock
  // Paced by the pacer (--accel): the feed, acceleration, minimum speed and clock.
  bool paced = false;
  PaceOptions pace;
  // The scenario, in cycles of the set (0: none): OVERRIDE from override_at on, a feed
  // hold and its end, a soft stop, the watchdog's timeout written after the last commit.
  std::uint32_t override_ = motion::kOverrideOne;
  std::uint64_t override_at = 0, hold_at = 0, resume_at = 0, soft_stop_at = 0;
  std::uint32_t watchdog = 0;
  // A part program at its planned speeds (--program --speeds): one entry per piece, the
  // block's ACCEL and VMIN (instead of paced or a feed).
  bool planned = false;
  std::vector<motion::PaceEntry> planned_entries;
  std::uint64_t planned_accel = 0;
  std::uint32_t planned_vmin = 0;
};
// The --bus options of `dda vectors` as given, and their checked values (InputError for
// a malformed timing, a feed without --bus, ...).
struct BusCli {
  bool bus = false, pipelined = false;
  std::string bridge;  // "axil", "spi" or empty (Wishbone)
  std::string build;   // a build spec (motion::parse_build), empty: the default build
  int abort_after = 0;
  std::string timing, timing_x, timing_y, timing_z;
  std::uint32_t polarity = 0, feed = 0;
  double feed_rate = 0, clock_hz = 0;
  double accel = 0, vmin = 0, override_pct = 100;
  std::uint64_t override_at = 0, hold_at = 0, resume_at = 0, soft_stop_at = 0;
  std::uint32_t watchdog = 0;
  CLI::Option *accel_opt = nullptr, *vmin_opt = nullptr, *override_opt = nullptr;
  // The run is a program at its planned speeds: --clock alone, --accel in mm/s^2 (the
  // planner's), --feed-rate and --vmin refused.
  bool planned = false;
  // A machine-input scenario (motion::kIoScenarios) instead of the arc.
  std::string io_scenario;
  bool scenario() const;  // any of the pacing and scenario options given
};
// The pacing and scenario options (cli/bus_pace.cpp): added to `dda vectors`, checked
// into the bus options, and run by the firmware after its last commit until the queue
// drains (InputError for a combination that never drains or a value out of range).
void add_bus_pace_options(CLI::App* vectors, BusCli& c);
void bus_pace_options(const BusCli& c, BusOptions& b);
// The entries of every piece of the plans run back to back (paced: planned by
// motion::pace_entries; else none).
std::vector<motion::PaceEntry> bus_pace_entries(const std::vector<Plan>& plans, const BusOptions& b);
// After the last commit: the scenario's events at their cycles (cycle: the set's cycle
// count, kept by the caller) and an abort abort_after cycles on, until the queue is
// empty, the block idle and no event is left.
void run_bus_scenario(motion::BusMaster& m, motion::MotionDriver& d, const BusOptions& b, const std::uint64_t& cycle);
void add_bus_options(CLI::App* vectors, BusCli& c);
BusOptions bus_options(const BusCli& c);
void write_bus_vector_set(const std::vector<Plan>& plans, const Options& opt, const BusOptions& bus);
// The bus bench's field table of a bus (tb/hdl/dda_bus_vec_fields.vh,
// dda_axil_vec_fields.vh, dda_spi_vec_fields.vh).
std::string bus_verilog_fields(motion::Bus bus = motion::Bus::wishbone);

// A Verilog macro NAME(cyc, exp, got) that prints the first field (most significant
// first, name and width) where the expected and the sampled words differ.
std::string report_macro(const std::string& macro, const std::vector<std::pair<std::string, int>>& fields);

// The bench's field table (tb/hdl/dda_vec_fields.vh), generated from the register table.
std::string verilog_fields(const hw::SignalTable& t = hw::signal_table());

}  // namespace dda::vec
