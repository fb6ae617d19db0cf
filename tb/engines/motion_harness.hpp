// SPDX-License-Identifier: Apache-2.0
// The motion block (rtl/dda_motion.v) under Verilator, in lockstep with its reference
// model (MotionModel) after every edge: the output ports, the block's registers
// (kBlockRegs) and the core's register table. On its Wishbone bus (rtl/dda_motion.v) or
// behind a bridge (rtl/dda_motion_axil.v, rtl/dda_motion_spi.v: then the bridge's
// registers too, against its reference model). A bus master (host/port/bus_master.hpp)
// drives it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/motion/bus_target.hpp"
#include "tb/engines/vl_sampler.hpp"
#include "tb/monitors/stepdir_monitor.hpp"

class VerilatedContext;

namespace dda::motion {

// The queue depth the harness' RTL is verilated with (-GDepthLog2, set once in
// tb/CMakeLists.txt): small in the tests' harness, so that they fill it; the RTL's
// default in the dda command's.
// The build the harness's verilated block is made with (dda_motion_harness_lib in
// cmake/dda_rtl.cmake): its queue depth, whether the machine inputs are built in, its
// axes.
inline constexpr int kHarnessDepthLog2 = DDA_MOTION_TEST_DEPTH_LOG2;
inline constexpr bool kHarnessInputs = DDA_MOTION_TEST_INPUTS != 0;
inline constexpr int kHarnessAxes = DDA_MOTION_TEST_AXES;
inline constexpr bool kHarnessPacer = DDA_MOTION_TEST_PACER != 0;
inline Build harness_build() { return Build{kHarnessDepthLog2, kHarnessInputs, kHarnessAxes, kHarnessPacer}; }

// The block's registers (kBlockRegs) and the core's register table of a Verilated
// dda_motion, by name below `scope` (e.g. "dut.dda_motion"). Throws GuardError naming a
// register the RTL lacks or holds at another width.
class VlBlockSampler {
 public:
  VlBlockSampler(const VerilatedContext& ctx, const std::string& scope, int depth_log2);
  ~VlBlockSampler();
  BlockRegs block() const;
  Signals core() const;

 private:
  struct Vars;
  std::unique_ptr<Vars> block_;
  std::unique_ptr<rtl::VlSampler> core_;
};

// Registers of given names and widths below `scope` of a Verilated model (a bridge's:
// kAxilRegs, kSpiRegs); GuardError as VlBlockSampler's.
class VlRegSampler {
 public:
  VlRegSampler(const VerilatedContext& ctx, const std::string& scope, const std::vector<BridgeReg>& regs);
  ~VlRegSampler();
  std::vector<std::uint64_t> read() const;

 private:
  struct Vars;
  std::unique_ptr<Vars> v_;
};

// Compares a bridge's registers (got) with its reference model's; "" when equal, else the
// first difference ("u_bridge.<register> is A, the reference model says B").
std::string compare_bridge(Bus bus, const std::vector<std::uint64_t>& got, const Bridge& model);

// Compares what a block holds with what the reference model holds; "" when equal, else
// the first difference ("<register> is A, the reference model says B").
std::string compare_block(const BlockRegs& got, const Signals& got_core, const MotionModel& m);

class MotionHarness : public HeldInputs {
 public:
  // GuardError for a bridge when the harness was built without them (the dda command's:
  // the tests' harness has them).
  explicit MotionHarness(const std::string& vcd = "", Bus bus = Bus::wishbone);
  ~MotionHarness() override;

  // One edge of both: the RTL and the model; then compares them and throws GuardError
  // naming the cycle and the first signal that differs.
  void tick(const BusIn& bus) override;
  const BusIn& bus_seen() const override { return seen_; }
  // The outputs after the last edge (the RTL's; equal to the model's).
  const BlockOutputs& outputs() const override { return out_; }
  const MotionModel& model() const override { return model_; }
  Bus bus() const override { return bus_; }
  std::uint64_t cycle() const { return cycle_; }

 private:
  class Top;  // the verilated top of the bus
  template <typename V>
  class TopOf;
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Top> top_;
  std::unique_ptr<VlBlockSampler> sampler_;
  MotionModel model_;
  std::unique_ptr<Bridge> bridge_;  // the bridge's reference model (none on Wishbone)
  Bus bus_;
  BusIn seen_;
  StepDirChecker timing_;
  BlockOutputs out_;
  std::uint64_t cycle_ = 0;
};

}  // namespace dda::motion
