// SPDX-License-Identifier: Apache-2.0
// SystemC model of one machine input (rtl/dda_input.v): same ports and registers.
#pragma once

#include <systemc>

#include <cstdint>

namespace dda::sc {

SC_MODULE(dda_input) {
  sc_core::sc_in<bool> clk_i, rst_ni, pin_i, invert_i, tick_i;
  sc_core::sc_in<std::uint32_t> filter_i;
  sc_core::sc_out<bool> level_o, rise_o;

  SC_HAS_PROCESS(dda_input);
  explicit dda_input(sc_core::sc_module_name name);

  // The registers (names as in the RTL and motion::kBlockRegs below u_io.u_*).
  sc_core::sc_signal<bool> s1_q{"s1_q"}, s2_q{"s2_q"}, lvl_q{"lvl_q"};
  sc_core::sc_signal<std::uint32_t> cnt_q{"cnt_q"};

 private:
  bool flip() const;  // the filtered level changes on this edge
  void comb();
  void seq();
};

}  // namespace dda::sc
