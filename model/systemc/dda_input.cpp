// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_input.hpp"

namespace dda::sc {

dda_input::dda_input(sc_core::sc_module_name name) : sc_core::sc_module(name) {
  SC_METHOD(comb);
  sensitive << tick_i << filter_i << s2_q << lvl_q << cnt_q;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

// The synchronized level has differed from the filtered one on filter_i ticks without a
// break, this one included (a filter of 0 as 1).
bool dda_input::flip() const {
  return s2_q.read() != lvl_q.read() && tick_i.read() && cnt_q.read() + 1 >= filter_i.read();
}

void dda_input::comb() {
  level_o.write(lvl_q.read());
  rise_o.write(flip() && s2_q.read());
}

void dda_input::seq() {
  if (!rst_ni.read()) {
    s1_q.write(false);
    s2_q.write(false);
    lvl_q.write(false);
    cnt_q.write(0);
    return;
  }
  const bool f = flip();
  s1_q.write(pin_i.read() != invert_i.read());
  s2_q.write(s1_q.read());
  lvl_q.write(lvl_q.read() != f);
  const bool differ = s2_q.read() != lvl_q.read();
  cnt_q.write(!differ || f ? 0 : tick_i.read() ? cnt_q.read() + 1 : cnt_q.read());
}

}  // namespace dda::sc
