// SPDX-License-Identifier: Apache-2.0
// Driving the motion block over its bus, the way firmware does: a bus master (Wishbone
// classic or pipelined cycles, AXI4-Lite or SPI frames through a bridge; random idle
// cycles) and a driver that queues commands, waits for the queue to drain and aborts.
// They run on any BusTarget: the reference model alone (ModelTarget: `dda vectors --bus`
// records its cycles), or the RTL beside the model (engines/motion_harness.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string_view>
#include <vector>

#include "motion/bridges.hpp"
#include "motion/motion_model.hpp"
#include "motion/speed_monitor.hpp"

namespace dda::motion {

class BusTarget {
 public:
  virtual ~BusTarget() = default;
  virtual void set_reset(bool rst_n) = 0;
  virtual void set_ce(bool ce) = 0;
  // The machine's input pins from the next edge on.
  virtual void set_pins(const MachinePins& pins) = 0;
  // The pins as last set.
  virtual const MachinePins& pins() const = 0;
  // One rising edge with these bus inputs (those of the target's bus).
  virtual void tick(const BusIn& bus) = 0;
  // The Wishbone inputs the block itself took on the last edge (behind a bridge, the
  // bridge's requests).
  virtual const BusIn& bus_seen() const = 0;
  // The outputs after the last edge.
  virtual const BlockOutputs& outputs() const = 0;
  // The reference model beside the target, after the last edge (equal to the target's
  // registers: every target checks that edge by edge).
  virtual const MotionModel& model() const = 0;
};

// A target between the bus master and another target that passes everything through to
// it: the monitors and the simulated machine below override what they watch or drive.
class BusTap : public BusTarget {
 public:
  explicit BusTap(BusTarget& inner) : t_(inner) {}
  void set_reset(bool rst_n) override { t_.set_reset(rst_n); }
  void set_ce(bool ce) override { t_.set_ce(ce); }
  void set_pins(const MachinePins& pins) override { t_.set_pins(pins); }
  const MachinePins& pins() const override { return t_.pins(); }
  void tick(const BusIn& bus) override { t_.tick(bus); }
  const BusIn& bus_seen() const override { return t_.bus_seen(); }
  const BlockOutputs& outputs() const override { return t_.outputs(); }
  const MotionModel& model() const override { return t_.model(); }

 protected:
  BusTarget& t_;
};

// A target that keeps the next edge's reset, ce_i and pins until its tick (the models
// and the harnesses).
class HeldInputs : public BusTarget {
 public:
  void set_reset(bool rst_n) override { rst_n_ = rst_n; }
  void set_ce(bool ce) override { ce_ = ce; }
  void set_pins(const MachinePins& pins) override { pins_ = pins; }
  const MachinePins& pins() const override { return pins_; }

 protected:
  bool rst_n_ = true, ce_ = true;
  MachinePins pins_;
};

// The reference model alone, on its Wishbone bus or behind a bridge (the bridge's
// reference model, motion/bridges.hpp); `on_edge` sees every edge's bus inputs as the
// host drove them, the inputs as the block took them, and the outputs and state after it.
class ModelTarget : public HeldInputs {
 public:
  explicit ModelTarget(int depth_log2 = kMaxDepthLog2, Bus bus = Bus::wishbone)
      : model_(depth_log2), bridge_(make_bridge(bus)) {}
  void tick(const BusIn& bus) override;
  const BusIn& bus_seen() const override { return seen_; }
  const BlockOutputs& outputs() const override { return out_; }
  const MotionModel& model() const override { return model_; }
  // The bridge's reference model (nullptr on Wishbone).
  const Bridge* bridge() const { return bridge_.get(); }
  std::function<void(const BusIn&, const BlockInputs&, const BlockOutputs&, const MotionModel&)> on_edge;

 private:
  MotionModel model_;
  std::unique_ptr<Bridge> bridge_;
  BusIn seen_;
  BlockOutputs out_;
};

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
  // A new monitor from here on (the one before, if any, is dropped).
  void watch(const MotionLimits& limits) { mon_.emplace(limits); }
  void unwatch() { mon_.reset(); }
  bool watching() const { return mon_.has_value(); }
  const SpeedMonitor& monitor() const { return mon_.value(); }

 private:
  std::optional<SpeedMonitor> mon_;
};

// One register access.
struct Transfer {
  bool we = false;
  std::uint32_t adr = 0, dat = 0;
  std::uint8_t sel = 0xF;  // byte lanes (wb_sel_i, WSTRB, the SPI command's)
};
// A bus master: one register access at a time on its bus.
class BusMaster {
 public:
  virtual ~BusMaster() = default;
  // Runs one access to its end; returns the read data (0 for a write).
  virtual std::uint32_t run(const Transfer& t) = 0;
  std::uint32_t read(std::uint32_t adr) { return run({false, adr, 0}); }
  void write(std::uint32_t adr, std::uint32_t dat, std::uint8_t sel = 0xF) { run({true, adr, dat, sel}); }
  // Cycles with the bus idle.
  void idle(int cycles);
  // Runs before every edge (to change reset or ce_i).
  std::function<void()> each_cycle;

 protected:
  explicit BusMaster(BusTarget& t) : t_(t) {}
  // One edge with these inputs, each_cycle first.
  void tick(const BusIn& b) {
    if (each_cycle) each_cycle();
    t_.tick(b);
  }
  BusTarget& t_;
};

// A Wishbone B4 master: one transfer at a time (the block answers one request every
// other cycle), classic (stb held through the ack cycle) or pipelined (stb dropped once
// the request is taken), with random idle cycles before each request.
class WishboneMaster : public BusMaster {
 public:
  WishboneMaster(BusTarget& t, std::uint64_t seed, bool pipelined, int idle_percent)
      : BusMaster(t), rng_(seed), pipelined_(pipelined), idle_percent_(idle_percent) {}
  std::uint32_t run(const Transfer& t) override;

 private:
  std::mt19937_64 rng_;
  bool pipelined_;
  int idle_percent_;
};

// An AXI4-Lite master (for the block behind rtl/dda_axil.v): a write's address and data
// each after a random delay (either first), a read's address; the response taken after a
// random delay; random idle cycles before each access.
class AxilMaster : public BusMaster {
 public:
  AxilMaster(BusTarget& t, std::uint64_t seed, int idle_percent)
      : BusMaster(t), rng_(seed), idle_percent_(idle_percent) {}
  std::uint32_t run(const Transfer& t) override;

 private:
  std::mt19937_64 rng_;
  int idle_percent_;
};

// An SPI master, mode 0 (for the block behind rtl/dda_spi.v): one frame per write; a
// read is its frame and a second one (a read of ID) that brings its data back. SCK's
// half period is `half` clocks or more (2: a quarter of the block's clock), a random
// one of up to twice that when `jitter`; CS_n's setup, hold and the gap between frames
// random above their minimums. Checks each status byte: the access done, the frame
// count advanced.
class SpiMaster : public BusMaster {
 public:
  SpiMaster(BusTarget& t, std::uint64_t seed, int half = 2, bool jitter = true)
      : BusMaster(t), rng_(seed), half_(half), jitter_(jitter) {}
  std::uint32_t run(const Transfer& t) override;
  // One frame of kSpiFrameBits bits as given (MSB first); returns the bits MISO carried.
  std::uint64_t frame(std::uint64_t mosi, int bits = kSpiFrameBits);

 private:
  void hold(BusIn& b, int cycles);
  int half();
  std::mt19937_64 rng_;
  int half_;
  bool jitter_;
  int count_ = -1;  // the status' access count expected next (-1: not known yet)
};

// A master for a target's bus: Wishbone (pipelined or classic), AXI4-Lite or SPI.
std::unique_ptr<BusMaster> make_master(Bus bus, BusTarget& t, std::uint64_t seed, bool pipelined, int idle_percent);

// A field's value in a register's word, and its bit (one-bit fields) by name.
std::uint32_t get_field(std::string_view reg, std::string_view field, std::uint32_t value);
std::uint32_t field_bit(std::string_view reg, std::string_view field);

// Firmware: queues commands (entry words in a random order when shuffled, then a
// commit, once the queue has room), waits for the queue to drain.
class MotionDriver {
 public:
  MotionDriver(BusMaster& m, std::uint64_t seed, bool shuffle = true) : m_(m), rng_(seed), shuffle_(shuffle) {}
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
  // A register by name.
  std::uint32_t read(std::string_view reg) { return m_.read(reg_offset(reg)); }
  void write(std::string_view reg, std::uint32_t value) { m_.write(reg_offset(reg), value); }
  // CTRL.clear: the sticky errors, their causes and TRIP.
  void clear();
  // The machine's inputs: IN_POLARITY (a bit per input, kInputs), IN_FILTER's clocks for
  // the switches and the probe, IN_MODE.
  void set_inputs(std::uint32_t polarity, std::uint32_t filter_switches, std::uint32_t filter_probe,
                  std::uint32_t mode);
  // CTRL.probe_arm.
  void arm_probe();
  // CTRL.snapshot, then SNAP_*: one clock's positions, cycle counter, level and count.
  struct Snapshot {
    Point pos;
    std::uint32_t cycle = 0, level = 0, done = 0;
  };
  Snapshot snapshot();
  // Three position registers (prefix "LATCH", "PROBE" or "SNAP": _X, _Y, _Z).
  Point positions(std::string_view prefix);
  // Until the block is at rest: the queue empty, the core idle, no soft stop running;
  // throws GuardError after max_polls.
  void wait_rest(int max_polls = 1000000);

 private:
  BusMaster& m_;
  std::mt19937_64 rng_;
  bool shuffle_;
};

}  // namespace dda::motion
