// SPDX-License-Identifier: Apache-2.0
// What the block's scripted scenarios (io_scenarios.hpp) share: the pacing they run at,
// a block reset, unpaced lines, waits and reads of the reference model's registers.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "host/driver/motion_driver.hpp"
#include "host/planner/planner.hpp"
#include "model/datapath/errors.hpp"

namespace dda::motion::scenario {

// Pacing: 2^-20 steps per clock^2, the minimum speed 1/1024 step per clock; speeds x
// 2^32 steps per clock, under the pacer's top speed (a step every 57 clocks at most):
// from 1/128 step per clock the braking distance is 32 steps.
constexpr std::uint32_t kAccel = 1u << 28, kVmin = 1u << 22;
constexpr std::uint32_t kFast = 1u << 25, kSlow = 1u << 23;  // 1/128 and 1/512 step per clock

inline std::uint32_t in_bit(std::string_view name) { return 1u << input_bit(name); }
inline std::int32_t reg32(const BusTarget& t, std::string_view r) { return std::int32_t(t.model().regs()[breg(r)]); }
inline std::uint32_t status(MotionDriver& d, std::string_view f) { return get_field("STATUS", f, d.read("STATUS")); }

// A line by `delta` queued unpaced: its feed increment lets the core iterate on one clock
// in `slowdown`.
inline void queue_unpaced(MotionDriver& d, Point delta, std::uint32_t slowdown) {
  const Plan plan = plan_line(Point{}, delta, Preload::Half);
  const std::uint32_t feed = std::uint32_t((std::uint64_t{1} << kFeedWidth) / slowdown);
  for (const auto& piece : plan.pieces) d.queue(piece.cmd, feed, piece.rot);
}

// A reset of a few edges: every scenario starts from the block's reset state.
inline void fresh(BusTarget& t) {
  t.set_pins(MachinePins{});
  t.set_reset(false);
  t.tick(BusIn{});
  t.tick(BusIn{});
  t.set_reset(true);
}

// Runs until `done` holds or `limit` cycles have passed.
template <typename F>
void run_until(BusMaster& m, F done, int limit, const char* what) {
  for (int i = 0; i < limit && !done(); ++i) m.idle(1);
  if (!done())
    throw GuardError(std::string("machine scenario: not within ") + std::to_string(limit) + " cycles: " + what);
}

}  // namespace dda::motion::scenario
