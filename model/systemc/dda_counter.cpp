// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_counter.hpp"

namespace dda::sc {

void dda_counter::comb() {
  const cnt_t c = cnt_q.read();
  active_o.write(c != 0);
  last_o.write(c == cnt_t(dec_i.read() ? 1 : 0));  // cnt_q - dec_i == 0
}

void dda_counter::seq() {
  if (!rst_ni.read()) {
    cnt_q.write(0);
  } else if (load_i.read()) {
    cnt_q.write(cnt_i.read());
  } else if (iterate_i.read() && dec_i.read()) {
    cnt_q.write(cnt_q.read() - 1);
  }
}

void dda_counter::trace(sc_core::sc_trace_file* tf, const std::string& p) const {
  sc_core::sc_trace(tf, cnt_q, p + ".cnt_q");
}

}  // namespace dda::sc
