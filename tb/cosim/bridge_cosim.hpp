// SPDX-License-Identifier: Apache-2.0
// Co-simulation of the block behind a bridge: the SystemC model of the bridged top
// (model/systemc/dda_motion_bridged.hpp) and the Verilated RTL (rtl/dda_motion_axil.v or
// rtl/dda_motion_spi.v, verilator --sc) on one sc_clock, driven by the same host bus
// signals. After every edge: every output port, every block register, the core's
// register table and every bridge register of the two are compared (a difference throws
// GuardError naming the register and the cycle), and the SystemC model with the block's
// and the bridge's reference models.
#pragma once

#include <memory>
#include <string>

#include "model/motion/bus_target.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/engines/sc_sampler.hpp"
#include "tb/monitors/stepdir_monitor.hpp"

namespace dda::motion {

class BridgeCosim : public HeldInputs {
 public:
  explicit BridgeCosim(Bus bus);  // Bus::axil or Bus::spi
  ~BridgeCosim() override;
  void tick(const BusIn& bus) override;
  const BusIn& bus_seen() const override { return seen_; }
  const BlockOutputs& outputs() const override { return out_; }
  const MotionModel& model() const override { return model_; }
  Bus bus() const override { return bus_; }
  std::uint64_t cycle() const { return cycle_; }

 private:
  struct Sim;  // the clock, the signals, both models (by bus)
  std::unique_ptr<Sim> sim_;
  Bus bus_;
  MotionModel model_;
  std::unique_ptr<Bridge> bridge_;
  StepDirChecker timing_;
  BlockOutputs out_;
  BusIn seen_;
  std::uint64_t cycle_ = 0;
};

}  // namespace dda::motion
