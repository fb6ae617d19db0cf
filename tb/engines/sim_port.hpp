// SPDX-License-Identifier: Apache-2.0
// The `sim` port of `dda run` (docs/programs.md, "Running a program live"): the motion
// block's RTL behind its SPI bridge (rtl/dda_motion_spi.v), verilated in the process and
// checked against its reference model on every edge (MotionHarness), with a simulated
// machine around it whose limit switches follow the pulses, reached by SPI frames (the
// frame-level path the hardware ports share). The machine's time is the block's clock
// counted. A counter on the step and direction pins measures the motion independently
// of the block's registers.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>

#include "host/run/live_run.hpp"
#include "model/machine/machine_sim.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/monitors/bus_monitors.hpp"

namespace dda::motion {

struct SimPortOptions {
  double clock_hz = 0;
  std::string vcd;           // the block's waveform ("": none)
  Point start;               // where the machine's axes are at the start, steps (the program's start)
  MachineSwitches switches;  // the simulated machine's limit switches, in block axes (steps)
  double estop_at = -1;      // s of machine time: the E-stop pressed from then on (<0: never)
  std::uint64_t seed = 1;
  // The host pauses (a slow host): before an access, with this chance in percent, it
  // leaves the link idle for a random time up to pause_ms.
  double pause_percent = 0, pause_ms = 0;
  double host_dies_at = -1;  // s: the host stops writing (the block left to its watchdog)
  // The pin monitor's windows: long enough that whole steps blur its acceleration by at
  // most 2% of this one (steps/s^2; SpeedMonitor::window_for).
  double accel_steps = 0;
};

// The host stopped at SimPortOptions::host_dies_at: thrown by the port's accesses; the
// block has run on alone until it came to rest.
class HostDied : public live::PortGone {
 public:
  using live::PortGone::PortGone;
};

class SimPort : public live::Port {
 public:
  explicit SimPort(const SimPortOptions& o);
  ~SimPort() override;
  BusMaster& bus() override { return *master_; }
  std::uint64_t clocks() const override { return cycles_; }
  void wait(std::uint64_t clocks) override;
  bool has_irq() const override { return true; }
  bool irq() const override;
  std::string pins_report(const Point& pos, bool& agree) const override;
  // The block's registers as the reference model holds them (a test's view).
  const MotionModel& model() const { return harness_->model(); }
  const SpeedMonitor& pins() const { return watch_->monitor(); }
  bool host_died() const { return host_died_; }

 private:
  class Host;  // the master's view: pauses, death
  SimPortOptions o_;
  std::unique_ptr<MotionHarness> harness_;
  std::unique_ptr<MachineSim> machine_;
  std::unique_ptr<SpeedWatch> watch_;
  std::unique_ptr<Host> host_;
  std::unique_ptr<SpiMaster> master_;
  std::uint64_t cycles_ = 0;
  bool host_died_ = false;
};

}  // namespace dda::motion
