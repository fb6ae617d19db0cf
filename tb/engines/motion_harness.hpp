// SPDX-License-Identifier: Apache-2.0
// The motion block (rtl/dda_motion.v) under Verilator, in lockstep with its reference
// model (MotionModel) after every edge: the output ports, the block's registers
// (kBlockRegs) and the core's register table. A Wishbone master (bus-functional model)
// drives it: classic or pipelined cycles, random idle cycles between requests.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "dda/motion_model.hpp"

class VerilatedContext;
class VerilatedVcdC;
class Vdda_motion;

namespace dda::motion {

// The queue depth the harness' RTL is verilated with (-GDepthLog2, set once in
// tb/CMakeLists.txt): small, so that the tests fill it.
inline constexpr int kHarnessDepthLog2 = DDA_MOTION_TEST_DEPTH_LOG2;

class MotionHarness {
 public:
  explicit MotionHarness(const std::string& vcd = "");
  ~MotionHarness();

  // Inputs of the next edge besides the bus (which the master drives).
  void set_reset(bool rst_n) { rst_n_ = rst_n; }
  void set_ce(bool ce) { ce_ = ce; }
  // One edge of both: the RTL and the model; then compares them and throws GuardError
  // naming the cycle and the first signal that differs.
  void tick(const BusIn& bus);
  // The outputs after the last edge (the RTL's; equal to the model's).
  const BlockOutputs& outputs() const { return out_; }
  const MotionModel& model() const { return model_; }
  std::uint64_t cycle() const { return cycle_; }

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Vdda_motion> top_;
  std::unique_ptr<VerilatedVcdC> vcd_;
  struct Var {
    std::string name;
    const void* p;
    int bytes;
    int width;
  };
  std::vector<Var> block_vars_, core_vars_;
  MotionModel model_;
  BlockOutputs out_;
  bool rst_n_ = true, ce_ = true;
  std::uint64_t cycle_ = 0;
};

// A Wishbone B4 master: runs a list of transfers on a harness, one at a time (the
// block answers one request every other cycle), in classic mode (stb held until ack)
// or pipelined mode (stb dropped once the request is taken), with random idle cycles
// before each request.
struct Transfer {
  bool we = false;
  std::uint32_t adr = 0, dat = 0;
};
class WishboneMaster {
 public:
  WishboneMaster(MotionHarness& h, std::uint64_t seed, bool pipelined, int idle_percent)
      : h_(h), rng_(seed), pipelined_(pipelined), idle_percent_(idle_percent) {}
  // Runs one transfer to its ack; returns the read data (0 for a write). `each_cycle`
  // runs before every edge (to change reset or ce_i).
  std::uint32_t run(const Transfer& t);
  std::uint32_t read(std::uint32_t adr) { return run({false, adr, 0}); }
  void write(std::uint32_t adr, std::uint32_t dat) { run({true, adr, dat}); }
  // Idle bus cycles.
  void idle(int cycles);
  std::function<void()> each_cycle;

 private:
  MotionHarness& h_;
  std::mt19937_64 rng_;
  bool pipelined_;
  int idle_percent_;
};

}  // namespace dda::motion
