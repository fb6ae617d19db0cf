// SPDX-License-Identifier: Apache-2.0
// The scenarios of the motion block's machine inputs (docs/design.md, "Machine inputs")
// and of the block at the ends of its ranges, written once: tests/test_motion_io.cpp runs them on the RTL beside the
// reference model and on the three engines, and `dda vectors --bus --io-scenario NAME` records them as bus vector sets
// from the reference model. Each resets the block, runs a simulated machine around it (MachineSim: its switches and
// probe follow the block's pulses) driven by the firmware driver, and hands every check of what the block must do to an
// Expect (the tests report each as a CHECK; the vector writer refuses a set whose
// scenario fails one).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <type_traits>

#include "model/motion/bus_target.hpp"

namespace dda::motion {

class Expect {
 public:
  using Report = std::function<void(bool ok, const std::string& what)>;
  explicit Expect(Report report) : report_(std::move(report)) {}
  // A check: `what` is its condition as written.
  void operator()(bool ok, const std::string& what) const { report_(ok, what); }
  // An equality, with both values in the report.
  template <typename A, typename B>
  void eq(const A& a, const B& b, const std::string& what) const {
    report_(same(a, b), what + " (" + text(a) + " vs " + text(b) + ")");
  }

 private:
  // Integers of any width and sign by their value.
  template <typename A, typename B, typename = std::enable_if_t<std::is_integral_v<A> && std::is_integral_v<B>>>
  static bool same(A a, B b) {
    return std::int64_t(a) == std::int64_t(b);
  }
  static bool same(const Point& a, const Point& b) { return a == b; }
  template <typename T>
  static std::string text(const T& v) {
    return std::to_string(v);
  }
  static std::string text(const Point& p);
  Report report_;
};

// What a scenario needs of the block beyond its machine inputs: the pacer (a ramped stop
// at ACCEL, the pacer's registers), the third axis, a bus faster than SPI (one register
// access a frame of some 300 clocks: a queue filled behind a short move, a filter's
// window timed between accesses).
enum ScenarioNeeds : unsigned { kNeedsPacer = 1, kNeedsZ = 2, kNeedsFastBus = 4 };
struct IoScenario {
  std::string_view name, what;
  void (*run)(BusTarget& block, const Expect& expect);
  unsigned needs = 0;  // ScenarioNeeds
};
// estop, limit-hard, limit-decel, homing, probing, snapshot, glitches; the block at the
// ends of its ranges (block_scenarios.cpp): overflow, limits, ranges.
extern const std::array<IoScenario, 10> kIoScenarios;
const IoScenario* find_io_scenario(std::string_view name);  // nullptr: no such scenario

void queue_overflow(BusTarget& block, const Expect& ex);
void each_limit(BusTarget& block, const Expect& ex);
void field_ranges(BusTarget& block, const Expect& ex);

}  // namespace dda::motion
