// SPDX-License-Identifier: Apache-2.0
// The SystemC model in a test bench: clock, reset, command and ce_i signals, an
// optional VCD, and the CoreHarness interface the shared driver uses. Elaborate one
// per process (SystemC cannot elaborate twice); run many arcs through it.
#pragma once

#include <memory>
#include <string>

#include "model/systemc/dda_core.hpp"
#include "tb/engines/core_driver.hpp"
#include "tb/engines/sc_sampler.hpp"

namespace dda::sc {

// Runs delta cycles until the combinational logic has settled at the current time.
void settle();

// The command fields as the command port's bit vector.
cmd_t command_bits(const CmdFields& fields);

class ScHarness : public CoreHarness {
 public:
  // vcd: waveform file name ("" for none); the factory builds the integrators.
  explicit ScHarness(const std::string& vcd = "", dda_core::IntegratorFactory factory = {});
  ~ScHarness() override;

  bool cmd_ready() override;
  const char* name() const override { return "systemc"; }

  dda_core& core() { return *core_; }
  // Finish the waveform file (also done by the destructor, which cannot report a failure).
  void close_trace();

 protected:
  void apply(const CoreInputs& in, bool cmd_changed) override;
  bool edge() override;
  Signals read_signals() override { return sampler_->read(); }
  PortValues read_ports() override;

 private:
  sc_core::sc_clock clk_{"clk", 10, sc_core::SC_NS, 0.5, 5, sc_core::SC_NS, true};
  sc_core::sc_signal<bool> rst_n_{"rst_n"}, ce_{"ce"}, cmd_valid_{"cmd_valid"}, cmd_ready_{"cmd_ready"};
  sc_core::sc_signal<cmd_t> cmd_{"cmd"};
  sc_core::sc_signal<bool> step_x_{"step_x"}, dir_x_{"dir_x"}, step_y_{"step_y"}, dir_y_{"dir_y"};
  sc_core::sc_signal<bool> step_z_{"step_z"}, dir_z_{"dir_z"};
  sc_core::sc_signal<bool> busy_{"busy"}, done_{"done"}, err_{"err"}, iter_{"iter"};
  // The pacer's norm operands (the scoreboard compares the registers they come from).
  sc_core::sc_signal<std::uint64_t> norm_v_x_{"norm_v_x"}, norm_v_y_{"norm_v_y"}, norm_v_z_{"norm_v_z"},
      norm_cap_{"norm_cap"}, norm_cap_z_{"norm_cap_z"};
  std::unique_ptr<dda_core> core_;
  std::unique_ptr<ScSampler> sampler_;
  sc_core::sc_trace_file* tf_ = nullptr;
  std::string vcd_;
};

}  // namespace dda::sc
