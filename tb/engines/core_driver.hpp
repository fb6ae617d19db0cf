// SPDX-License-Identifier: Apache-2.0
// Drives a DDA core (SystemC model or Verilated RTL) through arcs, clock by clock,
// the way a user's system would: reset, command handshake, ce_i pattern. Engine
// specific harnesses implement CoreHarness; the driving, sampling and checking is
// shared, so every engine is exercised and checked identically.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "host/accuracy/golden.hpp"
#include "model/datapath/core_model.hpp"
#include "tb/engines/scoreboard.hpp"

namespace dda {

// The output ports a harness reads, in kPorts order (checked by a static_assert beside
// each harness' read_ports()).
inline constexpr std::array<std::string_view, hw::kNumOutputs> kHarnessOutputs = {
    "cmd_ready_o", "step_x_o", "step_y_o", "dir_x_o", "dir_y_o", "step_z_o",
    "dir_z_o",     "busy_o",   "done_o",   "err_o",   "iter_o"};
static_assert(hw::outputs_are(kHarnessOutputs), "kHarnessOutputs no longer lists hw::kPorts' outputs in order");

class CoreHarness {
 public:
  virtual ~CoreHarness() = default;
  // Inputs, applied at the next rising edge.
  void set_reset(bool rst_n);
  void set_ce(bool ce);
  void set_command(bool valid, const CmdFields& cmd = {});
  // cmd_ready_o now (combinational: settles the inputs first).
  virtual bool cmd_ready() = 0;
  // One rising edge of the clock; an attached scoreboard checks it.
  void tick();
  // Every signal of the register table now (read once after each edge).
  const Signals& sample();
  std::uint64_t cycle() const { return cycle_; }
  virtual const char* name() const = 0;  // "systemc", "rtl", "cosim"
  // Every edge is checked against the reference model from the harness' first edge
  // on (the first thing a user does is a reset); a speed benchmark turns it off.
  void disable_checking() { checking_ = false; }
  bool checking() const { return checking_; }
  // Iterations the reference model has made (0 when not checking).
  std::uint64_t checked_iterations() const { return sb_ ? sb_->iterations() : 0; }

 protected:
  virtual void apply(const CoreInputs& in, bool cmd_changed) = 0;
  // One rising edge; returns cmd_ready_o as it was just before it (inputs settled).
  virtual bool edge() = 0;
  virtual Signals read_signals() = 0;
  // The output ports now (kPorts order; cmd_ready_o as it is now).
  virtual PortValues read_ports() = 0;
  std::uint64_t cycle_ = 0;

 private:
  CoreInputs in_;
  Signals last_{};
  bool have_last_ = false;  // last_ holds the signals since the last edge
  bool checking_ = true;
  std::unique_ptr<Scoreboard> sb_;
};

struct DriveOptions {
  std::function<bool(std::uint64_t cycle)> ce;  // ce_i per cycle; empty: always high
  bool check = true;                            // the arc must end on its end points
  bool keep_records = true;                     // return the sampled records
  // Reset the core after this many iterations (0: never).
  std::uint64_t reset_after = 0;
  // Reset the core on this clock edge counted from the command's presentation (0:
  // never): any edge, the load edge and ce_i stalls included.
  std::uint64_t reset_at_cycle = 0;
  // Edges with ce_i high after which a run without done_o is stopped (0: each piece's
  // iteration bound plus the loads and a margin, summed as the pieces come).
  std::uint64_t watchdog = 0;
};

struct DriveResult {
  RegState initial;  // registers sampled right after the first command was loaded
  std::vector<Iteration> records;
  std::uint64_t iterations = 0;
  std::uint64_t cycles = 0;  // from presenting the command to done (or to the reset)
  Point end;
  bool was_reset = false;
};

// Holds rst_ni low for `cycles` edges, then releases it.
void reset_core(CoreHarness& h, int cycles = 2);

// Drives a stream of pieces into the core: each piece's command is presented as soon as
// the one before it was taken (valid/ready), as a user's system hands commands over back
// to back, and every edge is sampled. piece() returns once the command before it has
// been taken (or at once for the first); finish() clocks until the last piece is done.
// Records go to on_record as the core makes them (and into the result with
// keep_records). The core must be idle (just reset, or after a run). Memory: the pieces
// presented and not yet done (at most two). Throws MismatchError (scoreboard, a piece
// ending off its end point), GuardError (err_o, watchdog).
class CoreDrive {
 public:
  CoreDrive(CoreHarness& h, const DriveOptions& opt = {}, std::function<void(const Iteration&)> on_record = {},
            std::function<void(const RegState&)> on_initial = {});
  void piece(const Piece& pc);
  DriveResult finish();
  bool was_reset() const { return res_.was_reset; }

 private:
  // One edge with the inputs as they are; false once the run is over (reset).
  bool edge();
  void present(const Piece& pc);
  CoreHarness& h_;
  DriveOptions opt_;
  std::function<void(const Iteration&)> on_record_;
  std::function<void(const RegState&)> on_initial_;
  DriveResult res_;
  std::uint64_t start_ = 0, ce_edges_ = 0, limit_ = 64, pieces_ = 0;
  std::deque<Piece> running_;  // presented and not yet done: the front is running
  bool offering_ = false;      // the back of running_ is offered and not yet taken
  bool started_ = false;       // the first command was taken
  Point pos_, from_;
  std::uint32_t done_pieces_ = 0;
};

// Runs one plan's pieces through CoreDrive (the watchdog from the golden run's
// iterations, unless given).
DriveResult drive_arc(CoreHarness& h, const Plan& plan, const DriveOptions& opt = {});

}  // namespace dda
