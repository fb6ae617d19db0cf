// SPDX-License-Identifier: Apache-2.0
// Control state machine: command handshake, iteration enable, done/err/iter pulses.
// Mirrors rtl/dda_ctrl.v.
#pragma once

#include "model/systemc/dda_sc_types.hpp"

namespace dda::sc {

SC_MODULE(dda_ctrl) {
  sc_core::sc_in<bool> clk_i, rst_ni;
  sc_core::sc_in<bool> cmd_valid_i, ce_i;
  sc_core::sc_in<bool> active_x_i, active_y_i, active_z_i;  // counters non-zero
  sc_core::sc_in<bool> can_x_i, can_y_i, can_z_i;           // active with a non-zero integrand
  sc_core::sc_in<bool> last_x_i, last_y_i, last_z_i;        // counters zero after this iteration
  sc_core::sc_out<bool> cmd_ready_o, load_o, iterate_o, busy_o;
  sc_core::sc_out<bool> done_o, err_o, iter_o;

  sc_core::sc_signal<sc_dt::sc_uint<hw::kStateWidth>> state_q{"state_q"};
  sc_core::sc_signal<bool> done_q{"done_q"}, err_q{"err_q"}, iter_q{"iter_q"};
  // Combinational decisions of a run cycle.
  sc_core::sc_signal<bool> finished{"finished"}, stalled{"stalled"}, finishing{"finishing"};

  SC_CTOR(dda_ctrl) {
    SC_METHOD(comb);
    sensitive << state_q << cmd_valid_i << ce_i << active_x_i << active_y_i << active_z_i << can_x_i << can_y_i
              << can_z_i << last_x_i << last_y_i << last_z_i << done_q << err_q << iter_q;
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
