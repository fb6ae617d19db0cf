// SPDX-License-Identifier: Apache-2.0
// Bus masters of the motion block: one register access at a time as Wishbone classic or
// pipelined cycles, or AXI4-Lite or SPI frames through a bridge, with random idle
// cycles, on any BusTarget (model/motion/bus_target.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <random>

#include "model/datapath/errors.hpp"
#include "model/motion/bus_target.hpp"

namespace dda::motion {

// The link to the block failed: a frame's status byte says bad, or a frame's access
// count did not advance (a host that reads it stops the machine: `dda run` exits 6).
class LinkError : public GuardError {
 public:
  using GuardError::GuardError;
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
// random delay; random idle cycles before each access. One write in four, once done,
// leaves its response waiting (BVALID high, BREADY low) while the reads after it go on;
// the next write takes it first.
class AxilMaster : public BusMaster {
 public:
  AxilMaster(BusTarget& t, std::uint64_t seed, int idle_percent)
      : BusMaster(t), rng_(seed), idle_percent_(idle_percent) {}
  std::uint32_t run(const Transfer& t) override;
  bool response_waiting() const { return b_waiting_; }
  // The reads made while a write's response waited.
  std::uint64_t reads_past_response() const { return reads_past_response_; }

 private:
  void take_response();
  std::mt19937_64 rng_;
  int idle_percent_;
  bool b_waiting_ = false;
  std::uint64_t reads_past_response_ = 0;
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
  // A write frame one edge short, or one or nine edges long: the block must make no
  // access, and the next frame's status must say bad (run() checks it).
  void stray_write(std::uint32_t adr, std::uint32_t dat);
  int strays() const { return strays_; }
  // The status byte of the last frame (docs/design.md, "SPI frame": done, bad, irq,
  // busy, count).
  std::uint32_t last_status() const { return status_; }

 private:
  void hold(BusIn& b, int cycles);
  int half();
  std::mt19937_64 rng_;
  int half_;
  bool jitter_;
  int count_ = -1;      // the status' access count expected next (-1: not known yet)
  bool stray_ = false;  // the last frame was of the wrong length
  int strays_ = 0;
  std::uint32_t status_ = 0;
};

// A master for a target's bus: Wishbone (pipelined or classic), AXI4-Lite or SPI.
std::unique_ptr<BusMaster> make_master(Bus bus, BusTarget& t, std::uint64_t seed, bool pipelined, int idle_percent);

}  // namespace dda::motion
