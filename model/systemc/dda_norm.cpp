// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_norm.hpp"

namespace dda::sc {

namespace {
std::uint64_t mask(int bits) { return bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1; }
}  // namespace

dda_norm::dda_norm(sc_core::sc_module_name name, int aw, int nf)
    : sc_core::sc_module(name),
      aw_(aw),
      nf_(nf),
      qw_(nf + 1),
      qc_((nf + 2) / 2),
      sw_(2 * (nf + 1)),
      rw_(4 * ((nf + 2) / 2)) {
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

// The divider, two steps: the remainder (the dividend itself on an axis' first clock:
// x's on clock 1, y's on QC + 1, z's on 2 QC + 1) against the divisor; each a quotient
// bit shifted in and the remainder doubled for the next step.
void dda_norm::divide() {
  const std::uint32_t cyc = cyc_q.read(), qc = std::uint32_t(qc_);
  const bool dx = cyc == 1, dy = cyc == qc + 1, dz = cyc == 2 * qc + 1, first = dx || dy || dz;
  const std::uint64_t v = dx ? v_x_i.read() : dy ? v_y_i.read() : v_z_i.read();
  const std::uint64_t d = first ? (dz ? cap_z_i.read() : cap_i.read()) : c_q.read();
  std::uint64_t n = first ? v : r_q.read(), q = q_q.read();
  for (int step = 0; step < 2; ++step) {
    const bool b = n >= d;
    n = ((b ? n - d : n) & mask(aw_)) << 1;
    q = (q << 1) | std::uint64_t(b);
  }
  r_q.write(n);
  q_q.write(q & mask(2 * qc_));
  if (first) c_q.write(d);
}

// The squarer, two steps: a += multiplier[0] ? multiplicand : 0, and multiplier[1] ?
// twice it : 0, the multiplicand shifting up, the multiplier down; on an axis' first
// clock both are the quotient just finished (the divider's top QW bits).
void dda_norm::square() {
  const std::uint32_t cyc = cyc_q.read(), qc = std::uint32_t(qc_);
  const bool sq0 = cyc == qc + 1 || cyc == 2 * qc + 1 || cyc == 3 * qc + 1;
  const std::uint64_t q = q_q.read() >> (2 * qc_ - qw_);
  const std::uint64_t mul = sq0 ? q : sq_q.read(), mcd = sq0 ? q : mc_q.read();
  const std::uint64_t add = ((mul & 1u) ? mcd : 0) + ((mul & 2u) ? (mcd << 1) & mask(sw_) : 0);
  a_q.write(((cyc == qc + 1 ? 0 : a_q.read()) + add) & mask(sw_));
  mc_q.write((mcd << 2) & mask(sw_));
  sq_q.write(mul >> 2);
}

// The root, two steps: each the radicand's next two bits into the remainder, against
// 4 root + 1.
void dda_norm::root() {
  std::uint64_t rem = rem_q.read(), rt = root_q.read(), s = s_q.read();
  for (int step = 0; step < 2; ++step) {
    const std::uint64_t rn = (rem << 2) | ((s >> (rw_ - 2)) & 3u);
    const std::uint64_t trial = (rt << 2) | 1u;
    const bool bit = rn >= trial;
    rem = (bit ? rn - trial : rn) & mask(qw_ + 1);
    rt = ((rt << 1) | std::uint64_t(bit)) & mask(qw_);
    s = (s << 2) & mask(rw_);
  }
  rem_q.write(rem);
  root_q.write(rt);
  s_q.write(s);
  if (cyc_q.read() == std::uint32_t(5 * qc_ + 1)) d_q.write(rt & mask(nf_ + 2));
}

void dda_norm::seq() {
  const std::uint32_t cyc = cyc_q.read(), last = std::uint32_t(5 * qc_ + 1), sum = std::uint32_t(4 * qc_ + 1);
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
  if (cyc <= std::uint32_t(3 * qc_)) divide();
  if (cyc > std::uint32_t(qc_) && cyc <= std::uint32_t(4 * qc_)) square();
  if (cyc == sum) {
    s_q.write(a_q.read());
    rem_q.write(0);
    root_q.write(0);
  }
  if (cyc > sum) root();
}

}  // namespace dda::sc
