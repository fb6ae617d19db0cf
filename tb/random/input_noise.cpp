// SPDX-License-Identifier: Apache-2.0
#include "tb/random/input_noise.hpp"

#include <string>

#include "host/driver/motion_driver.hpp"
#include "model/datapath/errors.hpp"

namespace dda::motion {

namespace {

constexpr std::uint32_t kAll = (1u << kNumInputs) - 1;
// The wire level of each input when active, before IN_POLARITY: estop_ni low, the others
// high.
constexpr std::uint32_t kActiveHigh = kAll & ~1u;

}  // namespace

void InputNoise::configure(bool redraw) {
  if (redraw) {
    polarity_ = std::uint32_t(rng_()) & kAll;
    filter_ = 2 + std::uint32_t(rng_() % 10);
    tick_ = std::uint32_t(rng_() % 3);
    probe_filter_ = 2 + std::uint32_t(rng_() % 5);
    homing_ = std::uint32_t(rng_() % 8);
  }
  forced_ = glitch_ = 0;
  glitch_left_ = 0;
  const std::uint32_t mode = homing_ << field_of("IN_MODE", "home_x").lsb | std::uint32_t(rng_() % 2);
  if (d_.inputs()) d_.set_inputs(polarity_, filter_, probe_filter_, mode, tick_);
  settle();
  d_.clear();
}

void InputNoise::settle() {
  forced_ = 0;
  m_.idle(switch_clocks() + int(probe_filter_) + 4);
}

void InputNoise::each_cycle() {
  // A glitch: one input active for no longer than its filter surely ignores (a switch's
  // (filter - 1) << tick clocks: its ticks come 2^tick clocks apart, so no more than
  // filter - 1 of them fall in it), then at rest again for at least a clock before the
  // next.
  const bool was = glitch_left_ > 0;
  if (glitch_left_ > 0) --glitch_left_;
  if (!was && rng_() % 200 == 0) {
    const int bit = kInputs[rng_() % kInputs.size()].bit;
    const std::uint32_t longest = bit == kProbeBit ? probe_filter_ - 1 : (filter_ - 1) << tick_;
    glitch_ = 1u << bit;
    glitch_left_ = 1 + int(rng_() % longest);
    ++glitches_;
  }
  const std::uint32_t active = forced_ | (glitch_left_ > 0 ? glitch_ : 0u);
  const std::uint32_t idle = ~(kActiveHigh ^ polarity_) & kAll;
  t_.set_pins(MachinePins::from_bits(idle ^ active));
}

void InputNoise::hold(std::uint32_t active, int cycles) {
  forced_ = active;
  m_.idle(cycles);
  forced_ = 0;
}

const char* InputNoise::trip() {
  const auto status = [&](std::string_view f) { return get_field("STATUS", f, d_.read("STATUS")) != 0; };
  const auto fail = [](const std::string& what) { throw GuardError("input noise: " + what); };
  if (get_field("CONFIG", "inputs", d_.read("CONFIG")) == 0) {
    // A block built without its inputs: every input held active stops nothing.
    m_.idle(int(rng_() % 300));
    forced_ = kAll;
    m_.idle(switch_clocks() + int(probe_filter_) + 3 + int(rng_() % 20));
    d_.wait_rest();  // the batch's motion runs to its end
    forced_ = 0;
    if (status("err") || status("aborted") || status("probed") || d_.read("TRIP") != 0 || d_.read("INPUTS") != 0 ||
        d_.positions("LATCH") != Point{} || d_.positions("PROBE") != Point{} || d_.positions("SNAP") != Point{})
      fail("an input acted on a block built without them");
    return "none built";
  }
  const std::uint32_t mode = d_.read("IN_MODE");
  // (of the block's axes: with two, Z's limits and home are not built)
  const unsigned axis = unsigned(rng_() % 3) % unsigned(d_.axes());
  m_.idle(int(rng_() % 300));
  const char* kind = nullptr;
  switch (rng_() % 4) {
    case 0:  // the E-stop: stopped, and stopped until cleared once released
      kind = "estop";
      hold(1u << input_bit("estop"), switch_clocks() + 3 + int(rng_() % 20));
      settle();
      if (!status("err_estop") || !status("aborted") || get_field("STATUS", "level", d_.read("STATUS")) != 0)
        fail("an E-stop did not stop the block");
      break;
    case 1: {  // both limits of an axis: a step of it either way stops the motion
      kind = "limit";
      forced_ = 3u << (kLimitBit + 2 * axis);
      d_.wait_rest();
      settle();
      const bool tripped = (d_.read("TRIP") & (3u << (kLimitBit + 2 * axis))) != 0;
      if (tripped != status("err_limit")) fail("TRIP and STATUS.err_limit disagree on a limit");
      break;
    }
    case 2:  // a home switch in homing mode: its edge stops the motion
      kind = "home";
      d_.write("IN_MODE", mode | 1u << (field_of("IN_MODE", "home_x").lsb + int(axis)));
      hold(1u << (kHomeBit + int(axis)), switch_clocks() + 2);
      d_.wait_rest();
      if ((d_.read("TRIP") & (1u << (kHomeBit + int(axis)))) == 0) fail("a home edge in homing mode did not trip");
      break;
    default:  // the armed probe, stopping
      kind = "probe";
      d_.write("IN_MODE", mode | field_bit("IN_MODE", "probe_stop"));
      d_.arm_probe();
      hold(1u << kProbeBit, int(probe_filter_) + 2);
      d_.wait_rest();
      if (!status("probed") || status("probe_armed")) fail("the armed probe did not latch");
      break;
  }
  settle();
  d_.write("IN_MODE", mode);
  d_.clear();
  if (status("err") || d_.read("TRIP") != 0) fail(std::string("a ") + kind + " trip did not clear");
  return kind;
}

}  // namespace dda::motion
