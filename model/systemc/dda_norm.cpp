// SPDX-License-Identifier: Apache-2.0
#include "dda_norm.hpp"

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

// Each divider: the remainder (the dividend itself on the first step) against the
// divisor; the quotient bit shifted in, the remainder doubled for the next step.
void dda_norm::divide() {
  const bool first = cyc_q.read() == 1;
  const std::uint64_t dx = first ? cap_i.read() : c_x_q.read(), dz = first ? cap_z_i.read() : c_z_q.read();
  struct Axis {
    std::uint64_t n, d;
    sc_core::sc_signal<std::uint64_t>&r, &q;
  };
  Axis ax[] = {{first ? v_x_i.read() : r_x_q.read(), dx, r_x_q, q_x_q},
               {first ? v_y_i.read() : r_y_q.read(), dx, r_y_q, q_y_q},
               {first ? v_z_i.read() : r_z_q.read(), dz, r_z_q, q_z_q}};
  for (auto& a : ax) {
    const bool b = a.n >= a.d;
    const std::uint64_t k = b ? a.n - a.d : a.n;
    a.r.write((k & mask(aw_)) << 1);
    a.q.write(((a.q.read() << 1) | std::uint64_t(b)) & mask(qw_));
  }
  if (first) {
    c_x_q.write(cap_i.read());
    c_z_q.write(cap_z_i.read());
  }
}

// Each squarer: a += q[0] ? q << i : 0, the multiplicand shifting up in r, the
// multiplier down in q (the first step starts from q itself).
void dda_norm::square() {
  const bool sq0 = cyc_q.read() == std::uint32_t(qw_ + 1);
  struct Axis {
    sc_core::sc_signal<std::uint64_t>&r, &q, &a;
  };
  Axis ax[] = {{r_x_q, q_x_q, a_x_q}, {r_y_q, q_y_q, a_y_q}, {r_z_q, q_z_q, a_z_q}};
  for (auto& a : ax) {
    const std::uint64_t q = a.q.read(), m = sq0 ? q : a.r.read();
    a.a.write(((sq0 ? 0 : a.a.read()) + ((q & 1u) ? m & mask(sw_) : 0)) & mask(sw_));
    a.r.write((m << 1) & mask(aw_ + 1));
    a.q.write(q >> 1);
  }
}

// The root: the sum's next two bits into the remainder, against 4 root + 1.
void dda_norm::root() {
  const std::uint64_t rn = (rem_q.read() << 2) | ((s_q.read() >> sw_) & 3u);
  const std::uint64_t trial = (root_q.read() << 2) | 1u;
  const bool bit = rn >= trial;
  rem_q.write((bit ? rn - trial : rn) & mask(qw_ + 1));
  root_q.write(((root_q.read() << 1) | std::uint64_t(bit)) & mask(qw_));
  s_q.write((s_q.read() << 2) & mask(sw_ + 2));
  if (cyc_q.read() == std::uint32_t(3 * qw_ + 1))
    d_q.write(((root_q.read() << 1) | std::uint64_t(bit)) & mask(nf_ + 2));
}

void dda_norm::seq() {
  const std::uint32_t cyc = cyc_q.read(), last = std::uint32_t(3 * qw_ + 1), sum = std::uint32_t(2 * qw_ + 1);
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
  if (cyc <= std::uint32_t(qw_)) divide();
  if (cyc > std::uint32_t(qw_) && cyc <= std::uint32_t(2 * qw_)) square();
  if (cyc == sum) {
    s_q.write(((a_x_q.read() + a_y_q.read() + a_z_q.read()) & mask(sw_)) << 2);
    rem_q.write(0);
    root_q.write(0);
  }
  if (cyc > sum) root();
}

}  // namespace dda::sc
