// SPDX-License-Identifier: Apache-2.0
// Checks a running core (SystemC model or RTL) against the cycle-level reference model
// (model/datapath/core_model.hpp), edge by edge: the harness reports the inputs of every edge and
// the signals sampled after it; every signal of the register table and cmd_ready_o are
// compared. The checker is fed by the harness (a monitor), never by the driver.
#pragma once

#include <cstdint>
#include <string>

#include "host/accuracy/golden.hpp"
#include "model/datapath/core_model.hpp"

namespace dda {

// A signal differs between an engine and the reference model (or another engine).
class MismatchError : public GuardError {
 public:
  using GuardError::GuardError;
};

class Scoreboard {
 public:
  explicit Scoreboard(std::string engine) : engine_(std::move(engine)) {}
  // After an edge: the inputs it clocked in, the engine's cmd_ready_o before it (with
  // rst_ni high), its signals and its output ports after it. Throws MismatchError naming cmd_ready_o, or
  // the first signal of the table that differs (and the others), the iteration, the
  // cycle and the values.
  void after_edge(const CoreInputs& in, bool ready, const Signals& got, const PortValues& ports, std::uint64_t cycle);
  std::uint64_t iterations() const { return iters_; }
  const CoreModel& model() const { return model_; }

 private:
  // The output ports after an edge against those the reference state drives.
  void check_ports(const Signals& want, const PortValues& ports, std::uint64_t cycle) const;
  std::string engine_;
  CoreModel model_;
  std::uint64_t iters_ = 0;
};

// Compares two samples signal by signal (e.g. SystemC against RTL, every cycle).
// Returns "" or a description of the first difference.
std::string compare_samples(const Signals& a, const Signals& b);

}  // namespace dda
