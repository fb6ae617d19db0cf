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
  sensitive << advance_i << running_i << take_i << stepped_i << v_q << ph_q << busy_q << pend_q << first_q << due_q
            << fresh_q << d_q << cm_q;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

std::int64_t dda_pace::phase() const {
  const std::uint64_t sign = std::uint64_t{1} << kPhaseBits, r = ph_q.read();
  return (r & sign) != 0 ? std::int64_t(r) - std::int64_t(sign << 1) : std::int64_t(r);
}

// s + the phase (floor, also below 0) + the margin against the distance to go + the
// exit speed's braking distance, at kDistFrac bits.
bool dda_pace::decel() const {
  const std::int64_t eb =
      next_queued_i.read() ? std::int64_t(std::uint64_t(brake_q.read()) << (kDistFrac - kLenFrac)) : 0;
  const std::int64_t margin = std::int64_t{1} << (kDistFrac - kMarginShift);
  return std::int64_t(s_q.read()) + (phase() >> (kRampFrac - kDistFrac)) + margin >= std::int64_t(rem_q.read()) + eb;
}

std::uint64_t dda_pace::target() const {
  if (hold_i.read()) return 0;
  const std::uint64_t t_cr = eff_q.read();
  const std::uint64_t t_ex = next_queued_i.read() ? ramp(exit_q.read()) : 0;
  const std::uint64_t t_dn = decel() && accel_i.read() != 0 && t_ex < t_cr ? t_ex : t_cr;
  return std::max(t_dn, ramp(vmin_i.read()));
}

void dda_pace::comb() {
  const bool blocked = first_q.read() || due_q.read() || seen() || load() ||
                       busy_q.read() > std::uint32_t(kNormLatency - kNormOperandEdges + 1);
  const std::int64_t dd = std::int64_t(d_q.read() << (kRampFrac - kNormFrac));
  const bool it = advance_i.read() && running_i.read() && !blocked && phase() + std::int64_t(v_q.read()) >= dd;
  iterate_o.write(it);
  start_.write(take_i.read() || (free() && (seen() || due_q.read())));
  speed_o.write(v_q.read());
}

// The override's top bit first: each clock doubles the product so far and adds the
// cruise speed for the next bit; a take or an override change starts it again. The
// product at the ramp's scale: macc_q shifted up by kRampFrac - kSpeedFrac - log2 kOverrideOne.
void dda_pace::multiply() {
  const std::uint32_t top = 1u << (kOverrideBits - 1);
  const std::uint64_t msum = 2 * macc_q.read() + ((mplier_q.read() & top) != 0 ? cruise_q.read() : 0);
  std::uint64_t eff = eff_q.read();
  if (mcnt_q.read() != 0) {
    macc_q.write(msum);
    mplier_q.write((mplier_q.read() << 1) & ((1u << kOverrideBits) - 1));
    mcnt_q.write(mcnt_q.read() - 1);
    if (mcnt_q.read() == 1) eff = std::min((msum << (kRampFrac - kSpeedFrac)) / kOverrideOne, ramp(limit_q.read()));
  }
  // A take clamps the product in force to the new limit at once.
  if (take_i.read()) eff = std::min(eff, ramp(limit_i.read()));
  eff_q.write(eff);
  if (take_i.read() || override_i.read() != ovr_q.read()) {
    ovr_q.write(override_i.read());
    mplier_q.write(override_i.read());
    macc_q.write(0);
    mcnt_q.write(std::uint32_t(kOverrideClocks));
  }
}

void dda_pace::reset() {
  for (auto* r : {&v_q, &ph_q, &s_q, &rem_q, &d_q, &macc_q, &eff_q, &cd_q}) r->write(0);
  for (auto* r : {&cruise_q, &limit_q, &exit_q, &brake_q, &busy_q, &m_q, &cm_q, &ovr_q, &mplier_q, &mcnt_q})
    r->write(0);
  for (auto* r : {&pend_q, &first_q, &due_q, &fresh_q}) r->write(false);
}

// The norm unit (its d is new kNormLatency clocks after its start) and the hand-over of
// its d with the correction of the run's provisional iterations.
void dda_pace::norm_seq(bool it) {
  if (start_.read())
    busy_q.write(std::uint32_t(kNormLatency));
  else if (busy_q.read() != 0)
    busy_q.write(busy_q.read() - 1);
  if (it && !fresh_q.read()) m_q.write(m_q.read() + 1);
  const std::uint64_t cmask = (std::uint64_t{1} << kCorrectionWidth) - 1;
  if (cm_q.read() != 0) {
    cm_q.write(cm_q.read() >> 1);
    cd_q.write((cd_q.read() << 1) & cmask);
  }
  if (load()) {
    cm_q.write(m_q.read());
    cd_q.write(std::uint64_t(std::int64_t(d_.read()) - std::int64_t(d_q.read())) & cmask);
    d_q.write(d_.read());
    fresh_q.write(true);
    first_q.write(false);
  }
  if (start_.read()) {
    fresh_q.write(false);
    due_q.write(false);
    m_q.write(0);
  } else if (seen()) {
    due_q.write(true);
  }
  pend_q.write(it);
}

// v toward the target by at most a, with the braking distance s.
void dda_pace::ramp_seq() {
  const std::uint64_t v = v_q.read(), s = s_q.read(), t = target(), a = accel_i.read();
  const std::uint64_t vmin = ramp(vmin_i.read());
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

void dda_pace::seq() {
  if (!rst_ni.read()) {
    reset();
    return;
  }
  multiply();
  const bool it = iterate_o.read();
  // What the edge takes off the distance to go and the phase, x 2^-kNormFrac steps: d on
  // an iteration and this clock's part of the correction of the run's provisional
  // iterations.
  const bool correcting = cm_q.read() != 0;
  const std::int64_t amt = (it ? std::int64_t(d_q.read()) : 0) + correction_part();
  norm_seq(it);
  if (it || correcting) {
    const std::int64_t r = std::int64_t(rem_q.read()) - amt * (std::int64_t{1} << (kDistFrac - kNormFrac));
    rem_q.write(r > 0 ? std::uint64_t(r) : 0);
  }
  if (!running_i.read()) {
    ph_q.write(0);
  } else if (advance_i.read() || correcting) {
    const std::int64_t sub = amt * (std::int64_t{1} << (kRampFrac - kNormFrac));
    const std::int64_t next = std::min(phase() + (advance_i.read() ? std::int64_t(v_q.read()) : 0) - sub,
                                       (std::int64_t{1} << kPhaseBits) - 1);
    ph_q.write(std::uint64_t(next) & ((std::uint64_t{1} << kPhaseWidth) - 1));
  }
  if (advance_i.read() && running_i.read()) ramp_seq();
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
    pend_q.write(false);
    first_q.write(true);
    due_q.write(false);
    fresh_q.write(false);
    m_q.write(0);
    cm_q.write(0);  // (a correction left of the piece before is dropped with it)
  }
}

std::int64_t dda_pace::correction_part() const {
  if ((cm_q.read() & 1u) == 0) return 0;
  const std::uint64_t sign = std::uint64_t{1} << (kCorrectionWidth - 1);
  return std::int64_t(cd_q.read() ^ sign) - std::int64_t(sign);
}

}  // namespace dda::sc
