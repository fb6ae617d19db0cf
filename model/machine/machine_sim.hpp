// SPDX-License-Identifier: Apache-2.0
// A simulated machine around a motion block (any BusTarget): its axes move by the
// pulses the block's stages start (the reference model's rise_x/y/z, checked equal to
// the RTL's every edge), and its switches and probe drive the block's input pins from
// those positions, before every edge: limit switches at the ends of travel, home
// switches, a probe surface, each optionally wired active low. A test adds pulses of
// its own (glitches, an E-stop) with `force`.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

#include "model/motion/bus_target.hpp"

namespace dda::motion {

struct MachineSwitches {
  // Per axis (x, y, z): a limit switch, active at and beyond its position.
  std::array<std::optional<std::int64_t>, 3> limit_neg{}, limit_pos{};
  // A home switch, active at and beyond its position on the side home_positive says.
  std::array<std::optional<std::int64_t>, 3> home{};
  std::array<bool, 3> home_positive{};
  // The probe touches at and below this Z.
  std::optional<std::int64_t> probe_z;
  // Pins wired active low (a bit per input, kInputs' order; estop_ni is always low
  // active on the wire, its bit ignored here).
  std::uint32_t active_low = 0;
};

class MachineSim : public BusTap {
 public:
  MachineSim(BusTarget& inner, Point start, const MachineSwitches& sw) : BusTap(inner), phys_(start), sw_(sw) {}
  // The pins are the machine's, set before every edge: a test changes them with force.
  void tick(const BusIn& bus) override;
  // Where the machine's axes are (steps), and the switches.
  Point physical() const { return phys_; }
  MachineSwitches& switches() { return sw_; }
  // Changes the pins the machine drives before each edge (after the switches).
  std::function<void(MachinePins&)> force;

 private:
  Point phys_;
  MachineSwitches sw_;
};

}  // namespace dda::motion
