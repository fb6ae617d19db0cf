// SPDX-License-Identifier: Apache-2.0
#include "model/machine/machine_sim.hpp"

namespace dda::motion {

void MachineSim::tick(const BusIn& bus) {
  const std::array<std::int64_t, 3> p{phys_.x, phys_.y, phys_.z};
  std::uint32_t active = 0;  // kInputs' order, 1: the switch is active
  for (std::size_t j = 0; j < 3; ++j) {
    const auto& n = sw_.limit_neg[j];
    const auto& q = sw_.limit_pos[j];
    const auto& h = sw_.home[j];
    if (n && p[j] <= *n) active |= 1u << (kLimitBit + 2 * j);
    if (q && p[j] >= *q) active |= 1u << (kLimitBit + 2 * j + 1);
    if (h && (sw_.home_positive[j] ? p[j] >= *h : p[j] <= *h)) active |= 1u << (kHomeBit + j);
  }
  if (sw_.probe_z && p[2] <= *sw_.probe_z) active |= 1u << kProbeBit;
  // (estop_ni released: high)
  MachinePins pins = MachinePins::from_bits((active ^ (sw_.active_low & ~1u)) | 1u);
  if (force) force(pins);
  t_.set_pins(pins);
  t_.tick(bus);
  const MotionModel& m = t_.model();
  phys_.x += m.rise_x();
  phys_.y += m.rise_y();
  phys_.z += m.rise_z();
}

}  // namespace dda::motion
