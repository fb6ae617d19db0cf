// SPDX-License-Identifier: Apache-2.0
// Driving the motion block over its Wishbone bus, the way firmware does: a bus master
// (classic or pipelined cycles, random idle cycles) and a driver that queues commands,
// waits for the queue to drain and aborts. They run on any BusTarget: the reference
// model alone (ModelTarget: `dda vectors --bus` records its cycles), or the RTL beside
// the model (engines/motion_harness.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include "motion/motion_model.hpp"
#include "motion/speed_monitor.hpp"

namespace dda::motion {

class BusTarget {
 public:
  virtual ~BusTarget() = default;
  virtual void set_reset(bool rst_n) = 0;
  virtual void set_ce(bool ce) = 0;
  // One rising edge with these bus inputs.
  virtual void tick(const BusIn& bus) = 0;
  // The outputs after the last edge.
  virtual const BlockOutputs& outputs() const = 0;
  // The reference model beside the target, after the last edge (equal to the target's
  // registers: every target checks that edge by edge).
  virtual const MotionModel& model() const = 0;
};

// The reference model alone; `on_edge` sees every edge's inputs and the state after it.
class ModelTarget : public BusTarget {
 public:
  explicit ModelTarget(int depth_log2 = kMaxDepthLog2) : model_(depth_log2) {}
  void set_reset(bool rst_n) override { rst_n_ = rst_n; }
  void set_ce(bool ce) override { ce_ = ce; }
  void tick(const BusIn& bus) override;
  const BlockOutputs& outputs() const override { return out_; }
  const MotionModel& model() const override { return model_; }
  std::function<void(const BlockInputs&, const MotionModel&)> on_edge;

 private:
  MotionModel model_;
  BlockOutputs out_;
  bool rst_n_ = true, ce_ = true;
};

// Checks every finished piece's end point: a target between the master and the block
// that, on every edge where DONE_COUNT advances, compares the position counters with
// the next expected end point (the caller lists them with expect(), in queue order);
// an ERR_COUNT change (a planner's command that stalled) or a piece finished with no
// end point expected is an error too. flush() forgets the expectations (after an abort
// or a reset). Throws GuardError naming the piece and both positions.
class PieceMonitor : public BusTarget {
 public:
  explicit PieceMonitor(BusTarget& inner) : t_(inner) {}
  void set_reset(bool rst_n) override;
  void set_ce(bool ce) override { t_.set_ce(ce); }
  void tick(const BusIn& bus) override;
  const BlockOutputs& outputs() const override { return t_.outputs(); }
  const MotionModel& model() const override { return t_.model(); }
  void expect(Point end) { ends_.push_back(end); }
  void flush() {
    ends_.clear();
    next_ = 0;
  }
  std::uint64_t checked() const { return checked_; }

 private:
  BusTarget& t_;
  std::vector<Point> ends_;  // front: the next piece to finish
  std::size_t next_ = 0;
  std::uint64_t done_ = 0, err_ = 0, checked_ = 0;
  bool reset_ = false;
};

// Measures the motion at the pins: a target between the master and the block that hands
// every edge's step and direction pins (POLARITY undone) to a SpeedMonitor, which throws
// GuardError at the first window over its limits. It watches from its construction with
// limits, or between watch() (the machine at rest) and unwatch() (before a stop the
// limits do not hold for, such as an abort).
class SpeedWatch : public BusTarget {
 public:
  explicit SpeedWatch(BusTarget& inner) : t_(inner) {}
  SpeedWatch(BusTarget& inner, const MotionLimits& limits) : t_(inner) { watch(limits); }
  void set_reset(bool rst_n) override { t_.set_reset(rst_n); }
  void set_ce(bool ce) override { t_.set_ce(ce); }
  void tick(const BusIn& bus) override;
  const BlockOutputs& outputs() const override { return t_.outputs(); }
  const MotionModel& model() const override { return t_.model(); }
  // A new monitor from here on (the one before, if any, is dropped).
  void watch(const MotionLimits& limits) { mon_.emplace(limits); }
  void unwatch() { mon_.reset(); }
  bool watching() const { return mon_.has_value(); }
  const SpeedMonitor& monitor() const { return mon_.value(); }

 private:
  BusTarget& t_;
  std::optional<SpeedMonitor> mon_;
};

// A Wishbone B4 master: one transfer at a time (the block answers one request every
// other cycle), classic (stb held through the ack cycle) or pipelined (stb dropped once
// the request is taken), with random idle cycles before each request.
struct Transfer {
  bool we = false;
  std::uint32_t adr = 0, dat = 0;
  std::uint8_t sel = 0xF;  // byte lanes (wb_sel_i)
};
class WishboneMaster {
 public:
  WishboneMaster(BusTarget& t, std::uint64_t seed, bool pipelined, int idle_percent)
      : t_(t), rng_(seed), pipelined_(pipelined), idle_percent_(idle_percent) {}
  // Runs one transfer to its ack; returns the read data (0 for a write).
  std::uint32_t run(const Transfer& t);
  std::uint32_t read(std::uint32_t adr) { return run({false, adr, 0}); }
  void write(std::uint32_t adr, std::uint32_t dat, std::uint8_t sel = 0xF) { run({true, adr, dat, sel}); }
  void idle(int cycles);
  // Runs before every edge (to change reset or ce_i).
  std::function<void()> each_cycle;

 private:
  BusTarget& t_;
  std::mt19937_64 rng_;
  bool pipelined_;
  int idle_percent_;
};

// A field's value in a register's word, and its bit (one-bit fields) by name.
std::uint32_t get_field(std::string_view reg, std::string_view field, std::uint32_t value);
std::uint32_t field_bit(std::string_view reg, std::string_view field);

// Firmware: queues commands (entry words in a random order when shuffled, then a
// commit, once the queue has room), waits for the queue to drain.
class MotionDriver {
 public:
  MotionDriver(WishboneMaster& m, std::uint64_t seed, bool shuffle = true) : m_(m), rng_(seed), shuffle_(shuffle) {}
  // feed: the entry's feed increment (0: the core's full rate); pace: its pacing fields
  // (a cruise speed of 0: paced by the feed increment).
  void queue(const Command& c, std::uint32_t feed = 0, int axes = 0, const PaceEntry& pace = {});
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

 private:
  WishboneMaster& m_;
  std::mt19937_64 rng_;
  bool shuffle_;
};

}  // namespace dda::motion
