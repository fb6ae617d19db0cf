// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_linear.hpp"

namespace dda::sc {

void dda_linear::comb() {
  const sum_t s = sum_t(jr_q.read()) + sum_t(jv_q.read());
  sum.write(s);
  ovf_o.write(active_i.read() && s >= sum_t(cap_q.read()));
  can_o.write(active_i.read() && jv_q.read() != 0);
  jv_o.write(jv_q.read());
  cap_o.write(cap_q.read());
}

void dda_linear::seq() {
  if (!rst_ni.read()) {
    jv_q.write(0);
    jr_q.write(0);
    cap_q.write(0);
    return;
  }
  if (load_i.read()) {
    jv_q.write(jv_i.read());
    jr_q.write(jr_i.read());
    cap_q.write(cap_i.read());
    return;
  }
  if (!iterate_i.read() || !active_i.read()) return;
  const sum_t s = sum.read();
  jr_q.write(acc_t(ovf_o.read() ? sum_t(s - sum_t(cap_q.read())) : s));
}

void dda_linear::trace(sc_core::sc_trace_file* tf, const std::string& p) const {
  sc_core::sc_trace(tf, jv_q, p + ".jv_q");
  sc_core::sc_trace(tf, jr_q, p + ".jr_q");
  sc_core::sc_trace(tf, cap_q, p + ".cap_q");
  sc_core::sc_trace(tf, sum, p + ".sum");
  sc_core::sc_trace(tf, ovf_o, p + ".ovf_o");
}

}  // namespace dda::sc
