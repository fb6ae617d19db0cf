// SPDX-License-Identifier: Apache-2.0
// Driving the motion block over its bus, the way firmware does, through a bus master
// (host/port/bus_master.hpp): a driver that queues commands, waits for the queue to drain,
// sets the timings, the pacing and the inputs, and reads the positions.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string_view>

#include "host/port/bus_master.hpp"

namespace dda::motion {

// A field's value in a register's word, and its bit (one-bit fields) by name.
std::uint32_t get_field(std::string_view reg, std::string_view field, std::uint32_t value);
std::uint32_t field_bit(std::string_view reg, std::string_view field);

// Firmware: queues commands (entry words in a random order when shuffled, then a
// commit, once the queue has room), waits for the queue to drain.
class MotionDriver {
 public:
  MotionDriver(BusMaster& m, std::uint64_t seed, bool shuffle = true) : m_(m), rng_(seed), shuffle_(shuffle) {}
  // feed: the entry's feed increment (0: the core's full rate); pace: its pacing fields
  // (a cruise speed of 0: paced by the feed increment); ctrl_also: other CTRL bits the
  // commit's write sets (on the same edge).
  void queue(const Command& c, std::uint32_t feed = 0, int axes = 0, const PaceEntry& pace = {},
             std::uint32_t ctrl_also = 0);
  // Runs after each entry word queue() writes (a live host writes its watchdog there).
  std::function<void()> each_word;
  // Until the queue is empty and the core idle; throws GuardError after max_polls.
  void drain(int max_polls = 1000000);
  void preset(Point p);
  Point position();
  // An axis' step/dir timings ('x' or 'y'), written to STEP_* and DIR_*.
  void set_timings(char axis, const StageTimings& t);
  void set_polarity(std::uint32_t bits);
  // The pacer's settings: ACCEL, VMIN; OVERRIDE; a feed hold (CTRL.hold) and its end.
  void set_pacing(std::uint32_t accel, std::uint32_t vmin);
  void set_override(std::uint32_t value);
  void hold();
  void resume();
  // A register by name.
  std::uint32_t read(std::string_view reg) { return m_.read(reg_offset(reg)); }
  void write(std::string_view reg, std::uint32_t value) { m_.write(reg_offset(reg), value); }
  // CTRL.clear: the sticky errors, their causes and TRIP.
  void clear();
  // The machine's inputs: IN_POLARITY (a bit per input, kInputs), IN_FILTER (the
  // switches' ticks, the probe's clocks, the switches' tick: every 2^filter_tick clocks),
  // IN_MODE. Throws GuardError for a value its field does not hold.
  void set_inputs(std::uint32_t polarity, std::uint32_t filter_switches, std::uint32_t filter_probe, std::uint32_t mode,
                  std::uint32_t filter_tick = 0);
  // CTRL.probe_arm.
  void arm_probe();
  // CTRL.snapshot, then SNAP_*: one clock's positions, cycle counter, level and count.
  struct Snapshot {
    Point pos;
    std::uint32_t cycle = 0, level = 0, done = 0;
  };
  Snapshot snapshot();            // CTRL.snapshot, then the SNAP_* registers
  Snapshot snapshot_registers();  // the SNAP_* registers as they are
  // Three position registers (prefix "LATCH", "PROBE" or "SNAP": _X, _Y, _Z).
  Point positions(std::string_view prefix);
  // Until the block is at rest: the queue empty, the core idle, no soft stop running;
  // throws GuardError after max_polls.
  void wait_rest(int max_polls = 1000000);
  // Reads CONFIG: the block's build (docs/design.md, "Builds"). From then on queue()
  // refuses (GuardError) what a block of two axes would drop: an entry with Z motion or
  // an axes field; and set_inputs(), arm_probe() and snapshot() refuse on a block built
  // without its inputs, where they would do nothing; on a block built without its pacer,
  // queue() refuses an entry with a cruise speed (the block would run it at its feed
  // increment) and set_pacing() and set_override() refuse. Until then the driver takes
  // the block for the default build (three axes, the inputs, the pacer).
  void read_build();
  int axes() const { return axes_; }
  bool inputs() const { return inputs_; }
  bool pacer() const { return pacer_; }

 private:
  BusMaster& m_;
  std::mt19937_64 rng_;
  bool shuffle_;
  int axes_ = 3;
  bool inputs_ = true;
  bool pacer_ = true;
  void need_inputs(const char* what) const;
  void need_pacer(const char* what) const;
};

}  // namespace dda::motion
