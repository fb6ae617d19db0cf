// SPDX-License-Identifier: Apache-2.0
// SystemC model of one step/dir stage (rtl/dda_stepdir.v): same ports and registers.
#pragma once

#include <systemc>

#include <cstdint>

namespace dda::sc {

SC_MODULE(dda_stepdir) {
  sc_core::sc_in<bool> clk_i, rst_ni, flush_i, step_i, dir_i, tag_i;
  sc_core::sc_in<std::uint32_t> steplen_i, stepspace_i, dirsetup_i, dirhold_i;
  sc_core::sc_out<bool> step_o, dir_o, hold_o, rise_o, rise_dir_o, wait_o, tag_left_o, busy_o, pend_o, pdir_o;

  SC_HAS_PROCESS(dda_stepdir);
  explicit dda_stepdir(sc_core::sc_module_name name);

  // The registers (names as in the RTL and motion::kBlockRegs below u_sx / u_sy).
  sc_core::sc_signal<bool> step_q{"step_q"}, dir_q{"dir_q"}, pend_q{"pend_q"}, pdir_q{"pdir_q"}, tag_q{"tag_q"};
  sc_core::sc_signal<std::uint32_t> tf_q{"tf_q"}, ts_q{"ts_q"};

 private:
  // This cycle's decisions (the RTL's wires), from the registers and the timings.
  struct Wires {
    bool fall, change, dir_d, rise, step_d, pend_d, pdir_d, rise_n;
    std::uint32_t tf_d, ts_d;
  };
  Wires wires() const;
  void comb();
  void seq();
};

}  // namespace dda::sc
