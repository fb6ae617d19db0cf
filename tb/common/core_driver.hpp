// Drives a DDA core (SystemC model or Verilated RTL) through arcs, clock by clock,
// the way a user's system would: reset, command handshake, ce_i pattern. Engine
// specific harnesses implement CoreHarness; the driving, sampling and checking is
// shared, so every engine is exercised and checked identically.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "dda/golden.hpp"
#include "scoreboard.hpp"

namespace dda {

class CoreHarness {
 public:
  virtual ~CoreHarness() = default;
  // Inputs, applied at the next rising edge.
  virtual void set_reset(bool rst_n) = 0;
  virtual void set_ce(bool ce) = 0;
  virtual void set_command(bool valid, const std::vector<std::uint32_t>& words) = 0;
  virtual bool cmd_ready() = 0;
  // One rising edge of the clock.
  virtual void tick() = 0;
  // The architectural registers (and adder outputs) now.
  virtual CoreSample sample() = 0;
  std::uint64_t cycle() const { return cycle_; }
  virtual const char* name() const = 0;  // "systemc", "rtl"

 protected:
  std::uint64_t cycle_ = 0;
};

struct DriveOptions {
  std::function<bool(std::uint64_t cycle)> ce;  // ce_i per cycle; empty: always high
  bool check = true;                            // scoreboard against the golden model
  bool keep_records = true;                     // return the sampled records
  // Reset the core after this many iterations (0: never).
  std::uint64_t reset_after = 0;
  // Reset the core on this clock edge counted from the command's presentation (0:
  // never): any edge, the load edge and ce_i stalls included.
  std::uint64_t reset_at_cycle = 0;
};

struct DriveResult {
  RegState initial;  // registers sampled right after the first command was loaded
  std::vector<Iteration> records;
  std::uint64_t iterations = 0;
  std::uint64_t cycles = 0;  // from presenting the command to done (or to the reset)
  Point end;
  bool was_reset = false;
};

// Holds rst_ni low for `cycles` edges, then releases it.
void reset_core(CoreHarness& h, int cycles = 2);

// Runs one arc: hands over the command, clocks until done, samples every edge.
// Throws MismatchError (scoreboard), GuardError (err_o, watchdog).
DriveResult drive_arc(CoreHarness& h, const Plan& plan, const DriveOptions& opt = {});

}  // namespace dda
