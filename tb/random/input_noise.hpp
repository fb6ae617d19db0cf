// SPDX-License-Identifier: Apache-2.0
// Random asynchronous activity on the motion block's machine inputs, for the random mix:
// a run's input settings (IN_POLARITY, IN_FILTER, homing modes), the pins at rest by
// that polarity, glitches shorter than the filter on random inputs at random cycles
// (the block must ignore every one: the batches they fall in still end on their end
// points), and real trips that cut a batch short (an E-stop, a limit, a home switch in
// homing mode, the armed probe), each checked for what it must leave in STATUS and TRIP.
#pragma once

#include <cstdint>
#include <random>

#include "host/driver/motion_driver.hpp"

namespace dda::motion {

class InputNoise {
 public:
  InputNoise(BusTarget& t, WishboneMaster& m, MotionDriver& d, std::uint64_t seed) : t_(t), m_(m), d_(d), rng_(seed) {}
  // Draws the run's settings and writes them (after a reset too: the block forgot them),
  // waits for the filters to settle and clears what the reset levels tripped.
  void configure(bool redraw);
  // Before every edge: the pins, with a glitch now and then.
  void each_cycle();
  // A real trip on a random input in the middle of a batch; the block at rest after it,
  // the cause checked and cleared. Returns what tripped ("estop", "limit", "home",
  // "probe"; a limit or home the batch's motion never ran into may trip nothing). On a
  // block built without its inputs (CONFIG.inputs 0): every input held active while the
  // batch's motion runs to its end, checked to stop and latch nothing ("none built").
  const char* trip();
  std::uint64_t glitches() const { return glitches_; }

 private:
  void hold(std::uint32_t active, int cycles);  // inputs forced active for that long
  void settle();                                // the filters past, the pins at rest

  BusTarget& t_;
  WishboneMaster& m_;
  MotionDriver& d_;
  std::mt19937_64 rng_;
  int switch_clocks() const { return int(filter_ << tick_); }  // a switch's level holding that long is seen
  std::uint32_t polarity_ = 0, filter_ = 1, tick_ = 0, probe_filter_ = 1, homing_ = 0;
  std::uint32_t forced_ = 0;  // inputs held active (kInputs' order)
  std::uint32_t glitch_ = 0;  // the input a glitch holds active, for glitch_left_ more cycles
  int glitch_left_ = 0;
  std::uint64_t glitches_ = 0;
};

}  // namespace dda::motion
