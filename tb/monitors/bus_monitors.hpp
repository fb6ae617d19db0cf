// SPDX-License-Identifier: Apache-2.0
// Monitors between a bus master and the motion block (BusTaps): the end point of every
// finished piece, and the motion at the step and direction pins.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "model/motion/bus_target.hpp"
#include "tb/monitors/speed_monitor.hpp"

namespace dda::motion {

// Checks every finished piece's end point: a target between the master and the block
// that, on every edge where DONE_COUNT advances, compares the position counters with
// the next expected end point (the caller lists them with expect(), in queue order);
// an ERR_COUNT change (a planner's command that stalled) or a piece finished with no
// end point expected is an error too. flush() forgets the expectations (after an abort
// or a reset). Throws GuardError naming the piece and both positions.
class PieceMonitor : public BusTap {
 public:
  explicit PieceMonitor(BusTarget& inner) : BusTap(inner) {}
  void set_reset(bool rst_n) override;
  void tick(const BusIn& bus) override;
  void expect(Point end) { ends_.push_back(end); }
  void flush() {
    ends_.clear();
    next_ = 0;
  }
  std::uint64_t checked() const { return checked_; }

 private:
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
class SpeedWatch : public BusTap {
 public:
  explicit SpeedWatch(BusTarget& inner) : BusTap(inner) {}
  SpeedWatch(BusTarget& inner, const MotionLimits& limits) : BusTap(inner) { watch(limits); }
  void tick(const BusIn& bus) override;
  // A new monitor from here on (the one before, if any, is dropped); sub_clocks as
  // SpeedMonitor's.
  void watch(const MotionLimits& limits, std::uint64_t sub_clocks = 0) { mon_.emplace(limits, sub_clocks); }
  void unwatch() { mon_.reset(); }
  bool watching() const { return mon_.has_value(); }
  const SpeedMonitor& monitor() const { return mon_.value(); }

 private:
  std::optional<SpeedMonitor> mon_;
};

}  // namespace dda::motion
