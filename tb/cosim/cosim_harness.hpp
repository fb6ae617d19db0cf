// SPDX-License-Identifier: Apache-2.0
// Three-way co-simulation: the hand-written SystemC model and the Verilated RTL
// (verilator --sc) on one sc_clock, driven by the same signals. After every clock edge
// every signal of the register table and every output of the two is compared (a
// difference throws MismatchError naming the signal and the cycle); the harness'
// scoreboard checks the SystemC model against the reference model at every edge, so
// the RTL, equal to it at every cycle, is checked against the golden model too.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "model/systemc/dda_core.hpp"
#include "tb/engines/core_driver.hpp"
#include "tb/engines/sc_sampler.hpp"
#include "tb/engines/vl_sampler.hpp"

class Vdda_core_sc;

namespace dda::cosim {

class CosimHarness : public CoreHarness {
 public:
  CosimHarness();
  ~CosimHarness() override;

  bool cmd_ready() override;
  const char* name() const override { return "cosim"; }

  Signals sc_sample() const { return sc_sampler_->read(); }
  Signals rtl_sample() const { return rtl_sampler_->read(); }
  std::uint64_t compared_cycles() const { return compared_; }
  // Resolves a register table against both models (throws GuardError naming a signal
  // one of them lacks or holds at another width): the drift test's handle.
  void resolve(const hw::SignalTable& t) const;

 protected:
  void apply(const CoreInputs& in, bool cmd_changed) override;
  bool edge() override;
  Signals read_signals() override { return sc_sample(); }
  PortValues read_ports() override;

 private:
  sc_core::sc_clock clk_{"clk", 10, sc_core::SC_NS, 0.5, 5, sc_core::SC_NS, true};
  sc_core::sc_signal<bool> rst_n_{"rst_n"}, ce_{"ce"}, cmd_valid_{"cmd_valid"};
  sc_core::sc_signal<sc::cmd_t> cmd_{"cmd"};
  // Each model drives its own copy of every output.
  struct Outputs {
    sc_core::sc_signal<bool> cmd_ready, step_x, dir_x, step_y, dir_y, step_z, dir_z, busy, done, err, iter;
    std::array<sc_core::sc_signal<std::uint64_t>, 5> norm;  // norm_v_x_o .. norm_cap_z_o
  };
  Outputs sc_out_, rtl_out_;
  std::unique_ptr<sc::dda_core> sc_;
  std::unique_ptr<Vdda_core_sc> rtl_;
  std::unique_ptr<sc::ScSampler> sc_sampler_;
  std::unique_ptr<rtl::VlSampler> rtl_sampler_;
  std::uint64_t compared_ = 0;
};

}  // namespace dda::cosim
