// SPDX-License-Identifier: Apache-2.0
// The timing monitor of the motion block's axes (docs/design.md, "Step and direction
// timing"): a BusTarget between the bus master and the block that reads the step and
// direction outputs after every edge with POLARITY undone (an edge that a POLARITY write
// itself makes at the pins is not seen: set it while the axes are idle), and checks
// every edge against the axis' four timings (STEP_*/DIR_*, the block's registers before
// that edge: a timing written on an edge acts from the next one): a pulse high for at least max(steplen, 1) cycles, low
// for at least max(stepspace, 1) cycles between pulses, the direction stable at least dirsetup cycles before a rising
// edge and dirhold cycles after a falling one, and never changed while a pulse is high. It counts the pulses in their
// direction and checks after every edge that the position counters moved by exactly what went out (a preset written on
// the bus starts the count again), so no step is lost, added or counted twice. Throws
// GuardError naming the axis, the rule, the cycle and the figures. StepDirChecker is the
// check itself (the RTL harness and the co-simulation run it on every edge);
// StepDirMonitor puts it on any BusTarget.
#pragma once

#include <array>
#include <cstdint>

#include "model/motion/bus_target.hpp"

namespace dda::motion {

class StepDirChecker {
 public:
  // After an edge with these bus inputs and reset: the block's outputs and its registers
  // (the reference model's, kBlockRegs: the timings, polarity, position counters) after it.
  void edge(const BusIn& bus, bool rst_n, const BlockOutputs& o, const BlockRegs& r);
  // Pulses seen per axis (0: x, 1: y, 2: z) since the checker started.
  std::uint64_t pulses(int axis) const { return pulses_[std::size_t(axis)]; }
  // The shortest of each timing seen per axis, in cycles (kNone: not seen): pulse high,
  // low between pulses, direction before the first rising edge after a change, and
  // after a falling edge before a change.
  static constexpr std::uint64_t kNone = ~std::uint64_t{0};
  struct Shortest {
    std::uint64_t high = kNone, low = kNone, setup = kNone, hold = kNone;
  };
  const Shortest& shortest(int axis) const { return short_[std::size_t(axis)]; }

 private:
  struct Axis {
    bool step = false, dir = false;
    bool seen_fall = false, seen_dir = false;  // the timers below started
    bool turned = false;                       // a direction change since the last pulse
    std::uint64_t level_cycles = 0;            // cycles the step output has held its level
    std::uint64_t dir_cycles = 0;              // cycles the direction output has held
    std::uint64_t since_fall = 0;              // cycles since the last falling edge
    std::int64_t moved = 0;                    // pulses in their direction since the last preset or reset
    std::uint32_t pos0 = 0;                    // the position counter at that point
    // The timings the stage decides the next edge with: the registers before that edge.
    std::uint64_t len = 1, space = 1, setup = 0, hold = 0;
  };
  static void load_timings(Axis& x, const BlockRegs& r, int a);
  void check_axis(const BlockRegs& r, int a, bool step, bool dir, bool preset, std::uint32_t pos);

  std::array<Axis, kAxes.size()> ax_{};
  std::array<std::uint64_t, kAxes.size()> pulses_{};
  std::array<Shortest, kAxes.size()> short_{};
  bool started_ = false;
  std::uint64_t cycle_ = 0;
};

class StepDirMonitor : public BusTap {
 public:
  explicit StepDirMonitor(BusTarget& inner) : BusTap(inner) {}
  void set_reset(bool rst_n) override {
    rst_n_ = rst_n;
    t_.set_reset(rst_n);
  }
  void tick(const BusIn& bus) override {
    t_.tick(bus);
    c_.edge(t_.bus_seen(), rst_n_, t_.outputs(), t_.model().regs());
  }
  std::uint64_t pulses(int axis) const { return c_.pulses(axis); }
  const StepDirChecker::Shortest& shortest(int axis) const { return c_.shortest(axis); }

 private:
  StepDirChecker c_;
  bool rst_n_ = true;
};

}  // namespace dda::motion
