// SPDX-License-Identifier: Apache-2.0
// One axis' remaining-step counter (end-point judgement). Mirrors rtl/dda_counter.v.
#pragma once

#include "model/systemc/dda_sc_types.hpp"

namespace dda::sc {

SC_MODULE(dda_counter) {
  sc_core::sc_in<bool> clk_i, rst_ni;
  sc_core::sc_in<bool> load_i, iterate_i;
  sc_core::sc_in<cnt_t> cnt_i;
  sc_core::sc_in<bool> dec_i;      // this axis carries in this iteration
  sc_core::sc_out<bool> active_o;  // cnt_q != 0: the axis still adds
  sc_core::sc_out<bool> last_o;    // cnt_q is 0 after this iteration

  sc_core::sc_signal<cnt_t> cnt_q{"cnt_q"};

  SC_CTOR(dda_counter) {
    SC_METHOD(comb);
    sensitive << cnt_q << dec_i;
    SC_METHOD(seq);
    sensitive << clk_i.pos();
    dont_initialize();
  }

  void trace(sc_core::sc_trace_file * tf, const std::string& prefix) const;

 private:
  void comb();
  void seq();
};

}  // namespace dda::sc
