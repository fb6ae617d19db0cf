// SPDX-License-Identifier: Apache-2.0
#include "host/driver/motion_driver.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>
#include <string>

#include "model/datapath/errors.hpp"

namespace dda::motion {

std::uint32_t get_field(std::string_view reg, std::string_view field, std::uint32_t value) {
  const Field& f = field_of(reg, field);
  return (value >> f.lsb) & std::uint32_t((std::uint64_t{1} << f.width) - 1);
}

std::uint32_t field_bit(std::string_view reg, std::string_view field) { return 1u << field_of(reg, field).lsb; }

void MotionDriver::queue(const Command& c, std::uint32_t feed, int axes, const PaceEntry& pace,
                         std::uint32_t ctrl_also) {
  if (axes_ == 2 && (c.cnt_z != 0 || axes != 0))
    throw GuardError("motion driver: the block has two axes (CONFIG.axes): no Z motion or axes field");
  if (!pacer_ && pace.cruise != 0)
    throw GuardError("motion driver: the block has no pacer (CONFIG.pacer): no cruise speed; the feed increment paces");
  while (get_field("STATUS", "full", m_.read(reg_offset("STATUS")))) m_.idle(int(rng_() % 8));
  const std::vector<std::uint32_t> w = entry_words(c, feed, axes, pace);
  std::vector<std::size_t> order(w.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (shuffle_) std::shuffle(order.begin(), order.end(), rng_);
  for (const std::size_t k : order) {
    m_.write(reg_offset("ENTRY") + 4 * std::uint32_t(k), w[k]);
    if (each_word) each_word();
  }
  m_.write(reg_offset("CTRL"), field_bit("CTRL", "commit") | ctrl_also);
}

void MotionDriver::read_build() {
  const std::uint32_t config = m_.read(reg_offset("CONFIG"));
  axes_ = int(get_field("CONFIG", "axes", config));
  inputs_ = get_field("CONFIG", "inputs", config) != 0;
  pacer_ = get_field("CONFIG", "pacer", config) != 0;
}

void MotionDriver::need_pacer(const char* what) const {
  if (!pacer_)
    throw GuardError(std::string("motion driver: ") + what + ": the block is built without its pacer (CONFIG.pacer)");
}

void MotionDriver::need_inputs(const char* what) const {
  if (!inputs_)
    throw GuardError(std::string("motion driver: ") + what + ": the block is built without its inputs (CONFIG.inputs)");
}

void MotionDriver::drain(int max_polls) {
  for (int i = 0; i < max_polls; ++i) {
    const std::uint32_t st = m_.read(reg_offset("STATUS"));
    if (get_field("STATUS", "empty", st) && !get_field("STATUS", "busy", st)) return;
    m_.idle(int(rng_() % 16));
  }
  throw GuardError("motion driver: the queue did not drain");
}

void MotionDriver::preset(Point p) {
  m_.write(reg_offset("POS_X"), std::uint32_t(p.x));
  m_.write(reg_offset("POS_Y"), std::uint32_t(p.y));
  m_.write(reg_offset("POS_Z"), std::uint32_t(p.z));
}

void MotionDriver::set_timings(char axis, const StageTimings& t) {
  const std::string a(1, char(std::toupper(static_cast<unsigned char>(axis))));
  const std::string step = "STEP_" + a, dir = "DIR_" + a;
  const auto put = [](std::string_view r, std::string_view f, std::uint32_t v) {
    const Field& fl = field_of(r, f);
    if (v >> fl.width) throw GuardError("motion driver: " + std::string(r) + "." + std::string(f) + " out of range");
    return v << fl.lsb;
  };
  m_.write(reg_offset(step), put(step, "steplen", t.steplen) | put(step, "stepspace", t.stepspace));
  m_.write(reg_offset(dir), put(dir, "dirsetup", t.dirsetup) | put(dir, "dirhold", t.dirhold));
}

void MotionDriver::set_polarity(std::uint32_t bits) { m_.write(reg_offset("POLARITY"), bits); }

void MotionDriver::set_pacing(std::uint32_t accel, std::uint32_t vmin) {
  need_pacer("set_pacing");
  m_.write(reg_offset("ACCEL"), accel);
  m_.write(reg_offset("VMIN"), vmin);
}
void MotionDriver::set_override(std::uint32_t value) {
  need_pacer("set_override");
  m_.write(reg_offset("OVERRIDE"), value);
}
void MotionDriver::hold() { m_.write(reg_offset("CTRL"), field_bit("CTRL", "hold")); }
void MotionDriver::resume() { m_.write(reg_offset("CTRL"), field_bit("CTRL", "resume")); }

void MotionDriver::clear() { m_.write(reg_offset("CTRL"), field_bit("CTRL", "clear")); }
void MotionDriver::arm_probe() {
  need_inputs("arm_probe");
  m_.write(reg_offset("CTRL"), field_bit("CTRL", "probe_arm"));
}

void MotionDriver::set_inputs(std::uint32_t polarity, std::uint32_t filter_switches, std::uint32_t filter_probe,
                              std::uint32_t mode, std::uint32_t filter_tick) {
  need_inputs("set_inputs");
  const auto fits = [](std::string_view f, std::uint32_t v) { return v >> field_of("IN_FILTER", f).width == 0; };
  if (polarity >> kNumInputs || !fits("switches", filter_switches) || !fits("probe", filter_probe) ||
      !fits("tick", filter_tick) || mode >> 5)
    throw GuardError("motion driver: an input setting out of range");
  m_.write(reg_offset("IN_POLARITY"), polarity);
  m_.write(reg_offset("IN_FILTER"), filter_switches << field_of("IN_FILTER", "switches").lsb |
                                        filter_tick << field_of("IN_FILTER", "tick").lsb |
                                        filter_probe << field_of("IN_FILTER", "probe").lsb);
  m_.write(reg_offset("IN_MODE"), mode);
}

MotionDriver::Snapshot MotionDriver::snapshot() {
  need_inputs("snapshot");
  m_.write(reg_offset("CTRL"), field_bit("CTRL", "snapshot"));
  return snapshot_registers();
}

MotionDriver::Snapshot MotionDriver::snapshot_registers() {
  Snapshot s;
  s.pos = positions("SNAP");
  s.cycle = m_.read(reg_offset("SNAP_CYCLE"));
  s.level = m_.read(reg_offset("SNAP_LEVEL"));
  s.done = m_.read(reg_offset("SNAP_DONE"));
  return s;
}

Point MotionDriver::positions(std::string_view prefix) {
  const auto at = [&](const char* axis) { return std::int32_t(m_.read(reg_offset(std::string(prefix) + axis))); };
  return Point{at("_X"), at("_Y"), at("_Z")};
}

void MotionDriver::wait_rest(int max_polls) {
  for (int i = 0; i < max_polls; ++i) {
    const std::uint32_t st = m_.read(reg_offset("STATUS"));
    if (get_field("STATUS", "empty", st) && !get_field("STATUS", "busy", st) && !get_field("STATUS", "stopping", st))
      return;
    m_.idle(int(rng_() % 16));
  }
  throw GuardError("motion driver: the block did not come to rest");
}

Point MotionDriver::position() { return positions("POS"); }

}  // namespace dda::motion
