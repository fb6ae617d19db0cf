// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_motion_io.hpp"

namespace dda::sc {

namespace {

using motion::field_of;
using motion::reg_offset;

constexpr std::uint32_t kTripMask = (1u << motion::kTripBits) - 1;

}  // namespace

dda_motion_io::dda_motion_io(sc_core::sc_module_name name, const motion::Build& build) : sc_core::sc_module(name) {
  for (std::size_t i = 0; i < in_.size(); ++i) {
    in_[i] = std::make_unique<dda_input>(std::string(motion::kInputs[i].inst).c_str());
    dda_input& d = *in_[i];
    d.clk_i(clk_i);
    motion::Build all = build;
    all.inputs = true;  // (without the inputs the whole of u_io is held in reset)
    if (motion::input_built(motion::kInputs[i], all))
      d.rst_ni(rst_ni);
    else
      d.rst_ni(off_);
    d.pin_i(pin_[i]);
    d.invert_i(invert_[i]);
    const bool probe = motion::kInputs[i].bit == motion::kProbeBit;
    d.tick_i(probe ? every_ : sw_tick_);
    d.filter_i(probe ? filt_probe_q : filt_sw_q);
    d.level_o(lvl_[i]);
    d.rise_o(rise_[i]);
  }
  every_.write(true);
  SC_METHOD(comb_tick);
  sensitive << cycle_q << filt_tick_q;
  SC_METHOD(comb_pins);
  sensitive << estop_ni << limit_i << home_i << probe_i << pol_q;
  SC_METHOD(comb);
  sensitive << adr_i << step_i << dir_i << pend_i << pdir_i << mode_q << err_estop_q << err_limit_q << probe_armed_q
            << probed_q << trip_q << pol_q << filt_sw_q << filt_tick_q << filt_probe_q << latch_x_q << latch_y_q
            << latch_z_q << probe_x_q << probe_y_q << probe_z_q << snap_x_q << snap_y_q << snap_z_q << snap_cycle_q
            << snap_level_q << snap_done_q;
  for (std::size_t i = 0; i < in_.size(); ++i) sensitive << lvl_[i] << rise_[i];
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

// The pins in INPUTS' bit order, each with its sense: estop_ni active low unless
// IN_POLARITY inverts it, the others active high unless it does.
void dda_motion_io::comb_pins() {
  const std::uint32_t pins = std::uint32_t(estop_ni.read()) | (limit_i.read() & 0x3Fu) << motion::kLimitBit |
                             (home_i.read() & 7u) << motion::kHomeBit |
                             std::uint32_t(probe_i.read()) << motion::kProbeBit;
  const std::uint32_t invert = pol_q.read() ^ 1u;
  for (std::size_t i = 0; i < in_.size(); ++i) {
    const int b = motion::kInputs[i].bit;
    pin_[i].write(((pins >> b) & 1u) != 0);
    invert_[i].write(((invert >> b) & 1u) != 0);
  }
}

// The switches' filters count on the clocks whose cycle count has its low IN_FILTER.tick
// bits all 1.
void dda_motion_io::comb_tick() {
  const std::uint32_t mask = (1u << filt_tick_q.read()) - 1;
  sw_tick_.write((cycle_q.read() & mask) == mask);
}

dda_motion_io::Wires dda_motion_io::wires() const {
  Wires w;
  std::uint32_t rise = 0;
  for (std::size_t i = 0; i < in_.size(); ++i) {
    w.lvl |= std::uint32_t(lvl_[i].read()) << motion::kInputs[i].bit;
    rise |= std::uint32_t(rise_[i].read()) << motion::kInputs[i].bit;
  }
  w.estop = (w.lvl & 1u) != 0;
  // Stage j: its limits at bits kLimitBit + 2j (negative) and + 2j + 1 (positive).
  const std::uint32_t st = step_i.read(), di = dir_i.read(), pe = pend_i.read(), pd = pdir_i.read();
  const std::uint32_t to_neg = (st & di) | (pe & pd), to_pos = (st & ~di) | (pe & ~pd);
  for (int j = 0; j < 3; ++j) {
    const std::uint32_t neg = (w.lvl >> (motion::kLimitBit + 2 * j)) & 1u;
    const std::uint32_t pos = (w.lvl >> (motion::kLimitBit + 2 * j + 1)) & 1u;
    w.limit_hits |= (((to_neg >> j) & neg) << (2 * j)) | (((to_pos >> j) & pos) << (2 * j + 1));
  }
  w.limit_hit = w.limit_hits != 0;
  w.home_ev = (rise >> motion::kHomeBit) & (mode_q.read() >> field_of("IN_MODE", "home_x").lsb) & 7u;
  w.probe_ev = ((rise >> motion::kProbeBit) & 1u) != 0 && probe_armed_q.read();
  w.trip_now = std::uint32_t(w.estop) | w.limit_hits << motion::kLimitBit | w.home_ev << motion::kHomeBit;
  return w;
}

std::uint32_t dda_motion_io::read(std::uint32_t adr) const {
  const auto f = [](const char* reg, const char* field, std::uint32_t v) { return v << field_of(reg, field).lsb; };
  if (adr == reg_offset("INPUTS")) return wires().lvl;
  if (adr == reg_offset("IN_POLARITY")) return pol_q.read();
  if (adr == reg_offset("IN_FILTER"))
    return f("IN_FILTER", "switches", filt_sw_q.read()) | f("IN_FILTER", "tick", filt_tick_q.read()) |
           f("IN_FILTER", "probe", filt_probe_q.read());
  if (adr == reg_offset("IN_MODE")) return mode_q.read();
  if (adr == reg_offset("TRIP")) return trip_q.read();
  if (adr == reg_offset("LATCH_X")) return latch_x_q.read();
  if (adr == reg_offset("LATCH_Y")) return latch_y_q.read();
  if (adr == reg_offset("LATCH_Z")) return latch_z_q.read();
  if (adr == reg_offset("PROBE_X")) return probe_x_q.read();
  if (adr == reg_offset("PROBE_Y")) return probe_y_q.read();
  if (adr == reg_offset("PROBE_Z")) return probe_z_q.read();
  if (adr == reg_offset("SNAP_X")) return snap_x_q.read();
  if (adr == reg_offset("SNAP_Y")) return snap_y_q.read();
  if (adr == reg_offset("SNAP_Z")) return snap_z_q.read();
  if (adr == reg_offset("SNAP_CYCLE")) return snap_cycle_q.read();
  if (adr == reg_offset("SNAP_LEVEL")) return snap_level_q.read();
  if (adr == reg_offset("SNAP_DONE")) return snap_done_q.read();
  return 0;
}

void dda_motion_io::comb() {
  const Wires w = wires();
  const std::uint32_t mode = mode_q.read();
  const bool decel = ((mode >> field_of("IN_MODE", "limit_decel").lsb) & 1u) != 0;
  const bool probe_stop = ((mode >> field_of("IN_MODE", "probe_stop").lsb) & 1u) != 0;
  hard_o.write(w.estop || err_estop_q.read() || (w.limit_hit && !decel));
  soft_o.write((w.limit_hit && decel) || w.home_ev != 0 || (w.probe_ev && probe_stop));
  err_o.write(w.estop || w.limit_hit);
  probe_o.write(w.probe_ev);
  home_o.write(w.home_ev != 0);
  err_estop_o.write(err_estop_q.read());
  err_limit_o.write(err_limit_q.read());
  probe_armed_o.write(probe_armed_q.read());
  probed_o.write(probed_q.read());
  rd_o.write(read(adr_i.read()));
}

void dda_motion_io::seq() {
  if (!rst_ni.read()) {
    for (auto* s : {&pol_q, &filt_sw_q, &filt_tick_q, &filt_probe_q, &mode_q, &trip_q, &latch_x_q, &latch_y_q,
                    &latch_z_q, &probe_x_q, &probe_y_q, &probe_z_q, &snap_x_q, &snap_y_q, &snap_z_q, &snap_cycle_q,
                    &snap_level_q, &snap_done_q, &cycle_q})
      s->write(0);
    for (auto* s : {&err_estop_q, &err_limit_q, &probe_armed_q, &probed_q}) s->write(false);
    return;
  }
  const Wires w = wires();
  const std::uint32_t adr = adr_i.read(), wdat = wdat_i.read();
  const bool wr = wr_i.read(), clear = clear_i.read(), arm = probe_arm_i.read();
  if (wr && adr == reg_offset("IN_POLARITY")) pol_q.write(wdat & ((1u << motion::kNumInputs) - 1));
  if (wr && adr == reg_offset("IN_FILTER")) {
    const auto fld = [&](std::string_view f) {
      const auto& d = field_of("IN_FILTER", f);
      return (wdat >> d.lsb) & ((1u << d.width) - 1);
    };
    filt_sw_q.write(fld("switches"));
    filt_tick_q.write(fld("tick"));
    filt_probe_q.write(fld("probe"));
  }
  if (wr && adr == reg_offset("IN_MODE")) mode_q.write(wdat & 0x1Fu);
  err_estop_q.write((err_estop_q.read() && !clear) || w.estop);
  err_limit_q.write((err_limit_q.read() && !clear) || w.limit_hit);
  trip_q.write(((clear ? 0u : trip_q.read()) | w.trip_now) & kTripMask);
  if (trip_q.read() == 0 && w.trip_now != 0) {
    latch_x_q.write(pos_x_i.read());
    latch_y_q.write(pos_y_i.read());
    latch_z_q.write(pos_z_i.read());
  }
  probe_armed_q.write(arm || (probe_armed_q.read() && !w.probe_ev));
  probed_q.write(!arm && (probed_q.read() || w.probe_ev));
  if (w.probe_ev) {
    probe_x_q.write(pos_x_i.read());
    probe_y_q.write(pos_y_i.read());
    probe_z_q.write(pos_z_i.read());
  }
  if (snapshot_i.read()) {
    snap_x_q.write(pos_x_i.read());
    snap_y_q.write(pos_y_i.read());
    snap_z_q.write(pos_z_i.read());
    snap_cycle_q.write(cycle_q.read());
    snap_level_q.write(level_i.read());
    snap_done_q.write(done_count_i.read());
  }
  cycle_q.write(cycle_q.read() + 1);
}

}  // namespace dda::sc
