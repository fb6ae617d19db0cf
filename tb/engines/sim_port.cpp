// SPDX-License-Identifier: Apache-2.0
#include "tb/engines/sim_port.hpp"

#include <fmt/format.h>

#include <cmath>

#include "host/driver/motion_driver.hpp"

namespace dda::motion {

// Between the master and the block: the host's pauses before a frame, its death, the
// E-stop, and the machine's time.
class SimPort::Host : public BusTap {
 public:
  Host(BusTarget& inner, SimPort& port) : BusTap(inner), p_(port), rng_(port.o_.seed) {}
  void tick(const BusIn& bus) override {
    const SimPortOptions& o = p_.o_;
    if (dead_) throw HostDied("the host has stopped");
    if (o.host_dies_at >= 0 && double(p_.cycles_) >= o.host_dies_at * o.clock_hz) die();
    // A pause before a frame starts (CS_n falling).
    if (!bus.spi.csn && last_csn_ && o.pause_percent > 0 &&
        std::uniform_real_distribution<double>(0, 100)(rng_) < o.pause_percent) {
      const double most = o.pause_ms * 1e-3 * o.clock_hz;
      const auto n = std::uint64_t(std::uniform_real_distribution<double>(0, most)(rng_));
      for (std::uint64_t k = 0; k < n; ++k) edge(BusIn{});
    }
    last_csn_ = bus.spi.csn;
    edge(bus);
  }

 private:
  void edge(const BusIn& bus) {
    const SimPortOptions& o = p_.o_;
    if (o.estop_at >= 0 && !p_.machine_->force && double(p_.cycles_) >= o.estop_at * o.clock_hz)
      p_.machine_->force = [](MachinePins& q) { q.estop_n = false; };
    t_.tick(bus);
    ++p_.cycles_;
  }
  // The host stops with the bus idle (CS_n high): the block runs on alone until it
  // rests, for at most its watchdog and ten seconds more.
  void die() {
    dead_ = true;
    p_.host_died_ = true;
    const MotionModel& m = t_.model();
    const std::uint64_t wd = m.read(reg_offset("WATCHDOG"));
    const std::uint64_t most = wd + std::uint64_t(10 * p_.o_.clock_hz);
    for (std::uint64_t k = 0; k < most; ++k) {
      edge(BusIn{});
      const std::uint32_t st = m.read(reg_offset("STATUS"));
      if (get_field("STATUS", "empty", st) && !get_field("STATUS", "busy", st) && !get_field("STATUS", "stopping", st))
        break;
    }
    throw HostDied(fmt::format("the host stopped writing at {:.3f} s", p_.o_.host_dies_at));
  }
  SimPort& p_;
  std::mt19937_64 rng_;
  bool last_csn_ = true, dead_ = false;
};

SimPort::SimPort(const SimPortOptions& o) : o_(o) {
  harness_ = std::make_unique<MotionHarness>(o.vcd, Bus::spi);
  machine_ = std::make_unique<MachineSim>(*harness_, o.start, o.switches);
  watch_ = std::make_unique<SpeedWatch>(*machine_);
  // (It measures and reports; the limits are the caller's to compare.)
  MotionLimits l;
  l.clock_hz = o.clock_hz;
  l.max_accel = o.accel_steps;
  const std::uint64_t sub = SpeedMonitor::window_for(l);
  l.max_accel = 0;
  watch_->watch(l, sub);
  host_ = std::make_unique<Host>(*watch_, *this);
  master_ = std::make_unique<SpiMaster>(*host_, o.seed, 2, false);
  // Out of reset, the machine where the block's position counters start.
  host_->set_reset(false);
  master_->idle(2);
  host_->set_reset(true);
  master_->idle(2);
}

SimPort::~SimPort() = default;

void SimPort::wait(std::uint64_t clocks) { master_->idle(int(std::min<std::uint64_t>(clocks, 1u << 30))); }

bool SimPort::irq() const { return (master_->last_status() >> spi_part("irq").first & 1u) != 0; }

std::string SimPort::pins_report(const Point& pos, bool& agree) const {
  const SpeedMonitor& m = watch_->monitor();
  // (The counter starts at 0, the machine at the program's start.)
  const std::array<std::int64_t, 3> c = m.position();
  const std::array<std::int64_t, 3> p{o_.start.x + c[0], o_.start.y + c[1], o_.start.z + c[2]};
  agree = p[0] == pos.x && p[1] == pos.y && p[2] == pos.z;
  return fmt::format(
      "pins: {} {} {} steps, the start and the steps counted on the step/dir pins ({} the position registers); "
      "peak path speed {:.0f} steps/s, peak path acceleration {:.0f} steps/s^2",
      p[0], p[1], p[2], agree ? "equal to" : "NOT equal to", m.peak_speed(), m.peak_accel());
}

}  // namespace dda::motion
