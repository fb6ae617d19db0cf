// SPDX-License-Identifier: Apache-2.0
// The cycle-level reference model of the core: the control of docs/design.md
// ("Behaviour, edge by edge") around the golden datapath's next-state function, over
// the register table of hw_params.hpp. The vector writer, the scoreboards and the
// co-simulation take every control-level expectation from it; the golden model proper
// (datapath.hpp, runner.hpp) stays iteration-level.
#pragma once

#include <array>
#include <cstdint>

#include "model/datapath/datapath.hpp"
#include "model/datapath/hw_params.hpp"

namespace dda {

// The value of every signal of the register table (registers and probes), each masked
// to its width: what a harness samples from an engine and what the model holds.
using Signals = std::array<std::uint64_t, hw::kNumSignals>;
// The command word's fields as the hardware sees them (kCmdFields order, masked).
using CmdFields = std::array<std::uint64_t, hw::kCmdFields.size()>;
// The output ports (kPorts order, outputs only).
using PortValues = std::array<std::uint64_t, hw::kNumOutputs>;

// The inputs applied before one rising edge.
struct CoreInputs {
  bool rst_n = true;
  bool ce = true;
  bool cmd_valid = false;
  CmdFields cmd{};  // read only with cmd_valid
};

// What one edge did (the control's decisions of that cycle).
struct CoreEdge {
  bool ready = false;      // cmd_ready_o during the cycle
  bool load = false;       // a command was taken
  bool iterate = false;    // an iteration happened
  bool finishing = false;  // the running command ended (done_o after the edge)
  bool stalled = false;    // the running command stalled (err_o after the edge)
};

class CoreModel {
 public:
  // The state after reset (every register 0, idle).
  CoreModel() { settle(); }
  const Signals& state() const { return s_; }
  // cmd_ready_o during the current cycle with ce_i = ce (combinational).
  bool cmd_ready(bool ce) const;
  // One rising edge with these inputs.
  CoreEdge edge(const CoreInputs& in);
  // The output ports a state drives (cmd_ready_o given, it is combinational).
  static PortValues outputs(const Signals& s, bool ready);
  // The iteration an edge made, from the signals before and after it (an engine's
  // samples or the model's states): the golden model's record (iter, piece and pos are
  // the caller's).
  static Iteration iteration_record(const Signals& pre, const Signals& post);
  // Did the edge into `post` iterate, end a command, stall; and the step's moves.
  static bool iterated(const Signals& post);
  static bool done(const Signals& post);
  static bool err(const Signals& post);
  static bool busy(const Signals& s);
  static Point step_of(const Signals& post);  // (-1, 0, +1) per axis
  // The datapath registers a state holds (integrands sign-extended).
  static RegState datapath_regs(const Signals& s);

 private:
  void settle();  // recompute the probes from the registers
  Signals s_{};
};

// A golden command's values by field, in kCmdFields order, as the model holds them
// (signed, unmasked; a direction is kDirNeg or kDirPos): the one mapping of Command's
// members onto the command word's fields.
using CmdValues = std::array<std::int64_t, hw::kCmdFields.size()>;
CmdValues command_values(const Command& c);

// The command word's fields of a golden command (masked; no range check: see
// hw_command.hpp for the checked packing).
CmdFields command_fields_unchecked(const Command& c);

}  // namespace dda
