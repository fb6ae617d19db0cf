// SPDX-License-Identifier: Apache-2.0
// The third axis' linear integrator: constant integrand jv_q, accumulator jr_q and its
// own capacity cap_q (Bresenham's rule). Mirrors rtl/dda_linear.v register for register.
#pragma once

#include "model/systemc/dda_sc_types.hpp"

namespace dda::sc {

SC_MODULE(dda_linear) {
  sc_core::sc_in<bool> clk_i, rst_ni;
  sc_core::sc_in<bool> load_i;              // take the command's values
  sc_core::sc_in<bool> iterate_i;           // one iteration on this edge
  sc_core::sc_in<bool> active_i;            // this axis' counter is non-zero
  sc_core::sc_in<acc_t> jv_i, jr_i, cap_i;  // command fields
  sc_core::sc_out<bool> ovf_o;              // this axis carries
  sc_core::sc_out<bool> can_o;              // active and jv_q != 0: can still carry
  sc_core::sc_out<acc_t> jv_o, cap_o;       // the integrand and the capacity (the pacer's norm operands)

  // Architectural registers.
  sc_core::sc_signal<acc_t> jv_q{"jv_q"}, jr_q{"jr_q"}, cap_q{"cap_q"};
  // Combinational: the adder output jr_q + jv_q.
  sc_core::sc_signal<sum_t> sum{"sum"};

  SC_CTOR(dda_linear) {
    SC_METHOD(comb);
    sensitive << jr_q << jv_q << cap_q << active_i;
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
