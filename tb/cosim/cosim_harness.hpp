// Three-way co-simulation: the hand-written SystemC model and the Verilated RTL
// (verilator --sc) on one sc_clock, driven by the same signals. After every clock edge
// every register and every output of the two is compared (a difference throws
// MismatchError naming the register and the cycle); the shared driver's scoreboard
// checks the SystemC model against the golden model at every iteration, so the RTL,
// equal to it at every cycle, is checked against the golden model too.
#pragma once

#include <memory>
#include <string>

#include "core_driver.hpp"
#include "dda_core.h"

class Vdda_core_sc;

namespace dda::cosim {

class CosimHarness : public CoreHarness {
 public:
  CosimHarness();
  ~CosimHarness() override;

  void set_reset(bool rst_n) override { rst_n_.write(rst_n); }
  void set_ce(bool ce) override { ce_.write(ce); }
  void set_command(bool valid, const std::vector<std::uint32_t>& words) override;
  bool cmd_ready() override;
  void tick() override;
  CoreSample sample() override { return sc_sample(); }
  const char* name() const override { return "cosim"; }

  CoreSample sc_sample();
  CoreSample rtl_sample();
  std::uint64_t compared_cycles() const { return compared_; }

 private:
  sc_core::sc_clock clk_{"clk", 10, sc_core::SC_NS, 0.5, 5, sc_core::SC_NS, true};
  sc_core::sc_signal<bool> rst_n_{"rst_n"}, ce_{"ce"}, cmd_valid_{"cmd_valid"};
  sc_core::sc_signal<sc::cmd_t> cmd_{"cmd"};
  // Each model drives its own copy of every output.
  struct Outputs {
    sc_core::sc_signal<bool> cmd_ready, step_x, dir_x, step_y, dir_y, busy, done, err, iter;
  };
  Outputs sc_out_, rtl_out_;
  std::unique_ptr<sc::dda_core> sc_;
  std::unique_ptr<Vdda_core_sc> rtl_;
  std::uint64_t compared_ = 0;
};

}  // namespace dda::cosim
