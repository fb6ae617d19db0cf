// SPDX-License-Identifier: Apache-2.0
// SystemC model of the pacer's norm unit (rtl/dda_norm.v): same ports, registers and
// schedule (one divider and one squarer serving the three axes in turn, a square root,
// two bits per clock each).
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
  sc_core::sc_signal<std::uint64_t> r_q{"r_q"}, c_q{"c_q"}, q_q{"q_q"}, sq_q{"sq_q"}, mc_q{"mc_q"}, a_q{"a_q"},
      s_q{"s_q"}, rem_q{"rem_q"}, root_q{"root_q"}, d_q{"d_q"};

 private:
  void comb();
  void seq();
  void divide();  // one step of the divider
  void square();  // one step of the squarer
  void root();    // one step of the square root

  int aw_, nf_, qw_, qc_, sw_, rw_;  // (the RTL's AW, NF, QW, QC, SW, RW)
};

}  // namespace dda::sc
