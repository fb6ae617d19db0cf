// SPDX-License-Identifier: Apache-2.0
// Co-simulation of the motion block: its SystemC model (model/systemc/dda_motion.hpp) and
// the Verilated RTL (verilator --sc) on one sc_clock, driven by the same bus and ce_i
// signals. After every edge: every output port, every block register and the core's
// register table of the two are compared (a difference throws GuardError naming the
// register and the cycle), and the SystemC model is compared with the block's
// reference model (MotionModel), so both are checked against the golden side.
#pragma once

#include <memory>
#include <string>

#include "model/motion/bus_target.hpp"
#include "model/systemc/dda_motion.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/engines/sc_sampler.hpp"
#include "tb/monitors/stepdir_monitor.hpp"

class Vdda_motion_sc;

namespace dda::motion {

// A register of a SystemC model by its hierarchical name (a bool, 32- or 64-bit signal);
// the block's registers (kBlockRegs) below a dda_motion's name. GuardError if missing.
std::uint64_t sc_signal_value(const std::string& name);
BlockRegs sc_block_regs(const std::string& scope);

class MotionCosim : public BusTarget {
 public:
  MotionCosim();
  ~MotionCosim() override;
  void set_reset(bool rst_n) override { rst_n_v_ = rst_n; }
  void set_ce(bool ce) override { ce_v_ = ce; }
  void set_pins(const MachinePins& pins) override { pins_v_ = pins; }
  const MachinePins& pins() const override { return pins_v_; }
  // On the block's Wishbone bus (the bridges are not in the co-simulation).
  void tick(const BusIn& bus) override;
  const BusIn& bus_seen() const override { return seen_; }
  const BlockOutputs& outputs() const override { return out_; }
  const MotionModel& model() const override { return model_; }
  std::uint64_t cycle() const { return cycle_; }

 private:
  // Each model drives its own copy of every output (names prefixed sc_ or rtl_).
  struct Ports {
    explicit Ports(const std::string& p)
        : dat((p + "dat").c_str()),
          ack((p + "ack").c_str()),
          stall((p + "stall").c_str()),
          step_x((p + "step_x").c_str()),
          step_y((p + "step_y").c_str()),
          dir_x((p + "dir_x").c_str()),
          dir_y((p + "dir_y").c_str()),
          step_z((p + "step_z").c_str()),
          dir_z((p + "dir_z").c_str()),
          busy((p + "busy").c_str()),
          irq((p + "irq").c_str()) {}
    sc_core::sc_signal<std::uint32_t> dat;
    sc_core::sc_signal<bool> ack, stall, step_x, step_y, dir_x, dir_y, step_z, dir_z, busy, irq;
    BlockOutputs read() const;
  };
  template <typename M>
  void bind(M& m, Ports& p);
  BlockRegs sc_block() const;

  sc_core::sc_clock clk_{"clk", 10, sc_core::SC_NS, 0.5, 5, sc_core::SC_NS, true};
  sc_core::sc_signal<bool> rst_n_{"rst_n"}, ce_{"ce"}, cyc_{"cyc"}, stb_{"stb"}, we_{"we"};
  sc_core::sc_signal<std::uint32_t> adr_{"adr"}, dat_{"dat_i"}, sel_{"sel"};
  Ports sc_out_{"sc_"}, rtl_out_{"rtl_"};
  std::unique_ptr<sc::dda_motion> sc_;
  std::unique_ptr<Vdda_motion_sc> rtl_;
  std::unique_ptr<sc::ScSampler> sc_core_;
  std::unique_ptr<VlBlockSampler> rtl_sampler_;
  MotionModel model_;
  StepDirChecker timing_;
  BlockOutputs out_;
  BusIn seen_;
  std::uint64_t cycle_ = 0;
  bool rst_n_v_ = true, ce_v_ = true;  // applied with the next edge's bus inputs
  MachinePins pins_v_;
  sc_core::sc_signal<bool> estop_n_{"estop_n"}, probe_{"probe"};
  sc_core::sc_signal<std::uint32_t> limit_{"limit"}, home_{"home"};
};

}  // namespace dda::motion
