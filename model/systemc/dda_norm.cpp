// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_norm.hpp"

namespace dda::sc {

namespace {
std::uint64_t mask(int bits) { return bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1; }
}  // namespace

dda_norm::dda_norm(sc_core::sc_module_name name, int aw, int nf)
    : sc_core::sc_module(name), aw_(aw), nf_(nf), qw_(nf + 1), sw_(2 * (nf + 1)) {
  SC_METHOD(comb);
  sensitive << start_i << cyc_q << d_q;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

void dda_norm::comb() {
  busy_o.write(start_i.read() || cyc_q.read() != 0);
  d_o.write(d_q.read());
}

// The divider: the remainder (the dividend itself on an axis' first step: x's on step
// 1, y's on QW + 1, z's on 2 QW + 1) against the divisor; the quotient bit shifted in,
// the remainder doubled for the next step.
void dda_norm::divide() {
  const std::uint32_t cyc = cyc_q.read(), qw = std::uint32_t(qw_);
  const bool dx = cyc == 1, dy = cyc == qw + 1, dz = cyc == 2 * qw + 1, first = dx || dy || dz;
  const std::uint64_t v = dx ? v_x_i.read() : dy ? v_y_i.read() : v_z_i.read();
  const std::uint64_t n = first ? v : r_q.read();
  const std::uint64_t d = first ? (dz ? cap_z_i.read() : cap_i.read()) : c_q.read();
  const bool b = n >= d;
  const std::uint64_t k = b ? n - d : n;
  r_q.write((k & mask(aw_)) << 1);
  q_q.write(((q_q.read() << 1) | std::uint64_t(b)) & mask(qw_));
  if (first) c_q.write(d);
}

// The squarer: a += multiplier[0] ? multiplicand : 0, the multiplicand shifting up,
// the multiplier down; on an axis' first step both are the quotient just finished.
void dda_norm::square() {
  const std::uint32_t cyc = cyc_q.read(), qw = std::uint32_t(qw_);
  const bool sq0 = cyc == qw + 1 || cyc == 2 * qw + 1 || cyc == 3 * qw + 1;
  const std::uint64_t mul = sq0 ? q_q.read() : sq_q.read(), mcd = sq0 ? q_q.read() : mc_q.read();
  a_q.write(((cyc == qw + 1 ? 0 : a_q.read()) + ((mul & 1u) ? mcd : 0)) & mask(sw_));
  mc_q.write((mcd << 1) & mask(sw_));
  sq_q.write(mul >> 1);
}

// The root: the sum's next two bits into the remainder, against 4 root + 1.
void dda_norm::root() {
  const std::uint64_t rn = (rem_q.read() << 2) | ((s_q.read() >> sw_) & 3u);
  const std::uint64_t trial = (root_q.read() << 2) | 1u;
  const bool bit = rn >= trial;
  rem_q.write((bit ? rn - trial : rn) & mask(qw_ + 1));
  root_q.write(((root_q.read() << 1) | std::uint64_t(bit)) & mask(qw_));
  s_q.write((s_q.read() << 2) & mask(sw_ + 2));
  if (cyc_q.read() == std::uint32_t(5 * qw_ + 1))
    d_q.write(((root_q.read() << 1) | std::uint64_t(bit)) & mask(nf_ + 2));
}

void dda_norm::seq() {
  const std::uint32_t cyc = cyc_q.read(), last = std::uint32_t(5 * qw_ + 1), sum = std::uint32_t(4 * qw_ + 1);
  if (!rst_ni.read()) {
    cyc_q.write(0);
    d_q.write(0);
    return;
  }
  if (start_i.read()) {
    cyc_q.write(1);
    return;
  }
  if (cyc == 0) return;
  cyc_q.write(cyc == last ? 0 : cyc + 1);
  if (cyc <= std::uint32_t(3 * qw_)) divide();
  if (cyc > std::uint32_t(qw_) && cyc <= std::uint32_t(4 * qw_)) square();
  if (cyc == sum) {
    s_q.write(a_q.read() << 2);
    rem_q.write(0);
    root_q.write(0);
  }
  if (cyc > sum) root();
}

}  // namespace dda::sc
