// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_integrator.hpp"

namespace dda::sc {

void dda_integrator::comb() {
  const sum_t s = sum_t(jr_q.read()) + sum_t(jv_q.read());
  sum.write(s);
  // A negative integrand (top bit set) holds its axis: no add, no carry.
  const bool add = active_i.read() && !jv_q.read()[hw::kAccWidth - 1];
  ovf_o.write(add && carry(s, cap_i.read()));
  can_o.write(add && jv_q.read() != 0);
  jv_o.write(jv_q.read());
}

void dda_integrator::seq() {
  if (!rst_ni.read()) {
    jv_q.write(0);
    jr_q.write(0);
    inc_on_x_q.write(0);
    inc_on_y_q.write(0);
    return;
  }
  if (load_i.read()) {
    jv_q.write(jv_i.read());
    jr_q.write(jr_i.read());
    inc_on_x_q.write(inc_on_x_i.read());
    inc_on_y_q.write(inc_on_y_i.read());
    return;
  }
  if (!iterate_i.read()) return;
  if (active_i.read() && !jv_q.read()[hw::kAccWidth - 1]) {
    const sum_t s = sum.read();
    jr_q.write(acc_t(ovf_o.read() ? sum_t(s - sum_t(cap_i.read())) : s));
  }
  acc_t jv = jv_q.read();
  if (ovf_x_i.read()) jv = jv + inc_on_x_q.read();  // modulo 2^AccWidth
  if (ovf_y_i.read()) jv = jv + inc_on_y_q.read();
  jv_q.write(jv);
}

void dda_integrator::trace(sc_core::sc_trace_file* tf, const std::string& p) const {
  sc_core::sc_trace(tf, jv_q, p + ".jv_q");
  sc_core::sc_trace(tf, jr_q, p + ".jr_q");
  sc_core::sc_trace(tf, inc_on_x_q, p + ".inc_on_x_q");
  sc_core::sc_trace(tf, inc_on_y_q, p + ".inc_on_y_q");
  sc_core::sc_trace(tf, sum, p + ".sum");
  sc_core::sc_trace(tf, ovf_o, p + ".ovf_o");
}

}  // namespace dda::sc
