// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_pace.hpp"

#include <algorithm>

#include "model/motion/pace_params.hpp"

namespace dda::sc {

using namespace dda::motion;

namespace {
std::uint64_t ramp(std::uint64_t v) { return v << (kRampFrac - kSpeedFrac); }
}  // namespace

dda_pace::dda_pace(sc_core::sc_module_name name, int aw) : sc_core::sc_module(name), u_norm("u_norm", aw, kNormFrac) {
  u_norm.clk_i(clk_i);
  u_norm.rst_ni(rst_ni);
  u_norm.start_i(start_);
  u_norm.v_x_i(v_x_i);
  u_norm.v_y_i(v_y_i);
  u_norm.v_z_i(v_z_i);
  u_norm.cap_i(cap_i);
  u_norm.cap_z_i(cap_z_i);
  u_norm.busy_o(norm_busy_);
  u_norm.d_o(d_);
  SC_METHOD(comb);
  sensitive << advance_i << running_i << take_i << v_q << ph_q << busy_q << pend_q << d_;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

// s + the phase + the margin against the distance to go + the exit speed's braking
// distance, at kDistFrac bits.
bool dda_pace::decel() const {
  const std::uint64_t eb = next_queued_i.read() ? std::uint64_t(brake_q.read()) << (kDistFrac - kLenFrac) : 0;
  const std::uint64_t margin = std::uint64_t{1} << (kDistFrac - kMarginShift);
  return s_q.read() + (ph_q.read() >> (kRampFrac - kDistFrac)) + margin >= rem_q.read() + eb;
}

std::uint64_t dda_pace::target() const {
  if (hold_i.read()) return 0;
  const std::uint64_t t_cr = eff_q.read();
  const std::uint64_t t_ex = next_queued_i.read() ? ramp(exit_q.read()) : 0;
  const std::uint64_t t_dn = decel() && accel_i.read() != 0 && t_ex < t_cr ? t_ex : t_cr;
  return std::max(t_dn, ramp(vmin_i.read()));
}

void dda_pace::comb() {
  const bool d_valid = busy_q.read() == 0 && !pend_q.read();
  const std::uint64_t dd = d_.read() << (kRampFrac - kNormFrac);
  const bool it = advance_i.read() && running_i.read() && d_valid && ph_q.read() + v_q.read() >= dd;
  iterate_o.write(it);
  start_.write(take_i.read() || it);
  speed_o.write(v_q.read());
}

// A bit of the override per clock adds the cruise speed, shifting up; a take or an
// override change starts it again (the RTL's mcand_q: cruise << (kRampFrac - kSpeedFrac
// - 8), 8 = log2 kOverrideOne).
void dda_pace::multiply() {
  const std::uint64_t msum = macc_q.read() + ((mplier_q.read() & 1u) ? mcand_q.read() : 0);
  std::uint64_t eff = eff_q.read();
  if (mcnt_q.read() != 0) {
    macc_q.write(msum);
    mcand_q.write(mcand_q.read() << 1);
    mplier_q.write(mplier_q.read() >> 1);
    mcnt_q.write(mcnt_q.read() - 1);
    if (mcnt_q.read() == 1) eff = std::min(msum, ramp(limit_q.read()));
  }
  // A take clamps the product in force to the new limit at once.
  if (take_i.read()) eff = std::min(eff, ramp(limit_i.read()));
  eff_q.write(eff);
  if (take_i.read() || override_i.read() != ovr_q.read()) {
    const std::uint64_t cruise = take_i.read() ? cruise_i.read() : cruise_q.read();
    ovr_q.write(override_i.read());
    mplier_q.write(override_i.read());
    mcand_q.write(ramp(cruise) / kOverrideOne);
    macc_q.write(0);
    mcnt_q.write(std::uint32_t(kOverrideClocks));
  }
}

void dda_pace::seq() {
  if (!rst_ni.read()) {
    v_q.write(0);
    ph_q.write(0);
    s_q.write(0);
    rem_q.write(0);
    cruise_q.write(0);
    limit_q.write(0);
    exit_q.write(0);
    brake_q.write(0);
    busy_q.write(0);
    pend_q.write(false);
    ovr_q.write(0);
    mplier_q.write(0);
    mcand_q.write(0);
    macc_q.write(0);
    mcnt_q.write(0);
    eff_q.write(0);
    return;
  }
  multiply();
  const bool it = iterate_o.read();
  const std::uint64_t v = v_q.read(), s = s_q.read(), t = target(), a = accel_i.read();
  const std::uint64_t vmin = ramp(vmin_i.read());
  const std::uint64_t d_dist = d_.read() << (kDistFrac - kNormFrac);
  if (pend_q.read() && stepped_i.read())
    busy_q.write(std::uint32_t(kNormLatency - 1));
  else if (busy_q.read() != 0)
    busy_q.write(busy_q.read() - 1);
  pend_q.write(it);
  if (it) rem_q.write(rem_q.read() > d_dist ? rem_q.read() - d_dist : 0);
  if (!running_i.read()) {
    ph_q.write(0);
  } else if (advance_i.read()) {
    const std::uint64_t next = ph_q.read() + v - (it ? d_.read() << (kRampFrac - kNormFrac) : 0);
    ph_q.write(std::min(next, (std::uint64_t{1} << kPhaseBits) - 1));
  }
  if (advance_i.read() && running_i.read()) {
    const auto dist = [](std::uint64_t speed) { return speed >> (kRampFrac - kDistFrac); };
    if (a == 0) {
      v_q.write(t);
      s_q.write(0);
    } else if (v < t) {
      v_q.write(t - v > a ? v + a : t);
      if (v > vmin) s_q.write(s + dist(v));
    } else if (v > t) {
      const std::uint64_t vn = v - t > a ? v - a : t;
      v_q.write(vn);
      if (vn > vmin) s_q.write(s > dist(vn) ? s - dist(vn) : 0);
      if (vn == 0) s_q.write(0);
    } else if (v == 0) {
      s_q.write(0);
    }
  }
  if (!running_i.read() && !take_i.read()) {
    v_q.write(0);
    s_q.write(0);
  }
  if (take_i.read()) {
    cruise_q.write(cruise_i.read());
    limit_q.write(limit_i.read());
    exit_q.write(exit_i.read());
    brake_q.write(brake_exit_i.read());
    rem_q.write(std::uint64_t(length_i.read()) << (kDistFrac - kLenFrac));
    busy_q.write(std::uint32_t(kNormLatency));
    pend_q.write(false);
  }
}

}  // namespace dda::sc
