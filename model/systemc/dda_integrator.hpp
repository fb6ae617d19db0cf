// SPDX-License-Identifier: Apache-2.0
// One axis' integrator: integrand jv_q, accumulator jr_q, integrand corrections.
// Mirrors rtl/dda_integrator.v register for register.
#pragma once

#include "model/systemc/dda_sc_types.hpp"

namespace dda::sc {

SC_MODULE(dda_integrator) {
  sc_core::sc_in<bool> clk_i, rst_ni;
  sc_core::sc_in<bool> load_i;     // take the command's values
  sc_core::sc_in<bool> iterate_i;  // one iteration on this edge
  sc_core::sc_in<bool> active_i;   // this axis' counter is non-zero
  sc_core::sc_in<acc_t> cap_i;
  sc_core::sc_in<acc_t> jv_i, jr_i, inc_on_x_i, inc_on_y_i;  // command fields
  sc_core::sc_in<bool> ovf_x_i, ovf_y_i;                     // both axes' carries of this iteration
  sc_core::sc_out<bool> ovf_o;                               // this axis carries
  sc_core::sc_out<bool> can_o;                               // active and jv_q != 0: can still carry
  sc_core::sc_out<acc_t> jv_o;                               // the integrand (the pacer's norm operand)

  // Architectural registers.
  sc_core::sc_signal<acc_t> jv_q{"jv_q"}, jr_q{"jr_q"}, inc_on_x_q{"inc_on_x_q"}, inc_on_y_q{"inc_on_y_q"};
  // Combinational: the adder output jr_q + jv_q.
  sc_core::sc_signal<sum_t> sum{"sum"};

  SC_CTOR(dda_integrator) {
    SC_METHOD(comb);
    sensitive << jr_q << jv_q << cap_i << active_i;
    SC_METHOD(seq);
    sensitive << clk_i.pos();
    dont_initialize();
  }
  virtual ~dda_integrator() = default;

  void trace(sc_core::sc_trace_file * tf, const std::string& prefix) const;

 protected:
  // The carry test of the accumulator (compare-and-subtract overflow).
  virtual bool carry(const sum_t& s, const acc_t& cap) const { return s >= cap; }

 private:
  void comb();
  void seq();
};

}  // namespace dda::sc
