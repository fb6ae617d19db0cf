// SPDX-License-Identifier: Apache-2.0
// SystemC model of the pacer's norm unit (rtl/dda_norm.v): same ports, registers and
// schedule (three dividers, three squarers, a square root, a bit per clock each).
#pragma once

#include <systemc>

#include <cstdint>

namespace dda::sc {

SC_MODULE(dda_norm) {
  sc_core::sc_in<bool> clk_i, rst_ni, start_i;
  sc_core::sc_in<std::uint64_t> v_x_i, v_y_i, v_z_i, cap_i, cap_z_i;
  sc_core::sc_out<bool> busy_o;
  sc_core::sc_out<std::uint64_t> d_o;

  SC_HAS_PROCESS(dda_norm);
  // aw: the integrands' width (the RTL's AW); nf: the fraction bits (NF).
  dda_norm(sc_core::sc_module_name name, int aw, int nf);

  // The registers (names as in the RTL).
  sc_core::sc_signal<std::uint32_t> cyc_q{"cyc_q"};
  sc_core::sc_signal<std::uint64_t> r_x_q{"r_x_q"}, r_y_q{"r_y_q"}, r_z_q{"r_z_q"}, c_x_q{"c_x_q"}, c_z_q{"c_z_q"},
      q_x_q{"q_x_q"}, q_y_q{"q_y_q"}, q_z_q{"q_z_q"}, a_x_q{"a_x_q"}, a_y_q{"a_y_q"}, a_z_q{"a_z_q"}, s_q{"s_q"},
      rem_q{"rem_q"}, root_q{"root_q"}, d_q{"d_q"};

 private:
  void comb();
  void seq();
  void divide();  // one step of the three dividers
  void square();  // one step of the three squarers
  void root();    // one step of the square root

  int aw_, nf_, qw_, sw_;
};

}  // namespace dda::sc
