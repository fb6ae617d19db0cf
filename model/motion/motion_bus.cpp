// SPDX-License-Identifier: Apache-2.0
#include "motion/motion_bus.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>
#include <string>

#include "datapath/errors.hpp"

namespace dda::motion {

void ModelTarget::tick(const BusIn& bus) {
  const BlockInputs in = block_inputs(rst_n_, ce_, bridge_ ? bridge_->wishbone() : bus, pins_);
  const BlockOutputs before = model_.outputs();
  model_.edge(in);
  seen_ = in.bus;
  out_ = model_.outputs();
  if (bridge_) {
    bridge_->edge(rst_n_, bus, before);
    bridge_->outputs(out_);
  }
  if (on_edge) on_edge(bus, in, out_, model_);
}

void PieceMonitor::set_reset(bool rst_n) {
  reset_ = !rst_n;
  t_.set_reset(rst_n);
}

void PieceMonitor::tick(const BusIn& bus) {
  t_.tick(bus);
  const BlockRegs& r = t_.model().regs();
  const std::uint64_t done = r[breg("done_count_q")], err = r[breg("err_count_q")];
  if (reset_) {  // the counters restart from 0, the queue is empty
    ends_.clear();
    next_ = 0;
    done_ = done;
    err_ = err;
    return;
  }
  if (err != err_) throw GuardError("piece monitor: a queued piece stalled (ERR_COUNT " + std::to_string(err) + ")");
  if (done == done_) return;
  // Two pieces can finish on one edge (a piece whose last step leaves as a piece with no
  // step waiting ends): the position is then the later one's end.
  const std::uint64_t finished = (done - done_) & 0xFFFFFFFFu;
  done_ = done;
  if (next_ + finished > ends_.size()) throw GuardError("piece monitor: a piece finished that was not queued");
  next_ += std::size_t(finished);
  const Point want = ends_[next_ - 1];
  const auto x = std::int32_t(r[breg("pos_x_q")]), y = std::int32_t(r[breg("pos_y_q")]);
  const auto z = std::int32_t(r[breg("pos_z_q")]);
  if (x != want.x || y != want.y || z != want.z) {
    throw GuardError("piece monitor: piece " + std::to_string(next_) + " finished at (" + std::to_string(x) + ", " +
                     std::to_string(y) + ", " + std::to_string(z) + "), its end point is (" + std::to_string(want.x) +
                     ", " + std::to_string(want.y) + ", " + std::to_string(want.z) + ")");
  }
  ++checked_;
}

std::uint32_t WishboneMaster::run(const Transfer& t) {
  std::uniform_int_distribution<int> pct(0, 99);
  while (pct(rng_) < idle_percent_) idle(1);
  bool taken = false;
  for (int guard = 0; guard < 64; ++guard) {
    BusIn b;
    b.cyc = true;
    b.stb = pipelined_ ? !taken : true;
    b.we = t.we;
    b.adr = t.adr;
    b.dat = t.dat;
    b.sel = t.sel;
    const bool stall = t_.outputs().stall;
    tick(b);
    if (b.stb && !stall) taken = true;
    if (taken && t_.outputs().ack) {
      const std::uint32_t data = t.we ? 0 : t_.outputs().dat;
      // Classic: the request stays on the bus through the ack cycle (the block stalls
      // it, so it is not taken twice). Pipelined: the next request may start now.
      if (!pipelined_) tick(b);
      return data;
    }
  }
  throw GuardError("Wishbone master: no ack within 64 cycles");
}

void BusMaster::idle(int cycles) {
  for (int i = 0; i < cycles; ++i) tick(BusIn{});
}

std::uint32_t get_field(std::string_view reg, std::string_view field, std::uint32_t value) {
  const Field& f = field_of(reg, field);
  return (value >> f.lsb) & std::uint32_t((std::uint64_t{1} << f.width) - 1);
}

std::uint32_t field_bit(std::string_view reg, std::string_view field) { return 1u << field_of(reg, field).lsb; }

void SpeedWatch::tick(const BusIn& bus) {
  t_.tick(bus);
  if (!mon_) return;
  const BlockOutputs& o = t_.outputs();
  const std::uint64_t pol = t_.model().regs()[breg("polarity_q")];
  const auto pin = [&](bool v, std::string_view f) { return v != (((pol >> field_of("POLARITY", f).lsb) & 1u) != 0); };
  mon_->edge({pin(o.step_x, "step_x"), pin(o.step_y, "step_y"), pin(o.step_z, "step_z")},
             {pin(o.dir_x, "dir_x"), pin(o.dir_y, "dir_y"), pin(o.dir_z, "dir_z")});
}

void MotionDriver::queue(const Command& c, std::uint32_t feed, int axes, const PaceEntry& pace) {
  while (get_field("STATUS", "full", m_.read(reg_offset("STATUS")))) m_.idle(int(rng_() % 8));
  const std::vector<std::uint32_t> w = entry_words(c, feed, axes, pace);
  std::vector<std::size_t> order(w.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (shuffle_) std::shuffle(order.begin(), order.end(), rng_);
  for (const std::size_t k : order) m_.write(reg_offset("ENTRY") + 4 * std::uint32_t(k), w[k]);
  m_.write(reg_offset("CTRL"), field_bit("CTRL", "commit"));
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
  m_.write(reg_offset("ACCEL"), accel);
  m_.write(reg_offset("VMIN"), vmin);
}
void MotionDriver::set_override(std::uint32_t value) { m_.write(reg_offset("OVERRIDE"), value); }
void MotionDriver::hold() { m_.write(reg_offset("CTRL"), field_bit("CTRL", "hold")); }
void MotionDriver::resume() { m_.write(reg_offset("CTRL"), field_bit("CTRL", "resume")); }

void MotionDriver::clear() { m_.write(reg_offset("CTRL"), field_bit("CTRL", "clear")); }
void MotionDriver::arm_probe() { m_.write(reg_offset("CTRL"), field_bit("CTRL", "probe_arm")); }

void MotionDriver::set_inputs(std::uint32_t polarity, std::uint32_t filter_switches, std::uint32_t filter_probe,
                              std::uint32_t mode) {
  const std::uint32_t fmax = (1u << kFilterWidth) - 1;
  if (polarity >> kNumInputs || filter_switches > fmax || filter_probe > fmax || mode >> 5)
    throw GuardError("motion driver: an input setting out of range");
  m_.write(reg_offset("IN_POLARITY"), polarity);
  m_.write(reg_offset("IN_FILTER"), filter_switches << field_of("IN_FILTER", "switches").lsb |
                                        filter_probe << field_of("IN_FILTER", "probe").lsb);
  m_.write(reg_offset("IN_MODE"), mode);
}

MotionDriver::Snapshot MotionDriver::snapshot() {
  m_.write(reg_offset("CTRL"), field_bit("CTRL", "snapshot"));
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
