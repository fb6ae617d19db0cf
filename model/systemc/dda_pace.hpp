// SPDX-License-Identifier: Apache-2.0
// SystemC model of the pacer (rtl/dda_pace.v): same ports, registers and norm unit
// (dda_norm), the reference model's (motion::Pacer) state register for register.
#pragma once

#include <systemc>

#include <cstdint>

#include "model/systemc/dda_norm.hpp"

namespace dda::sc {

SC_MODULE(dda_pace) {
  sc_core::sc_in<bool> clk_i, rst_ni, advance_i, running_i, take_i, next_queued_i, hold_i, stepped_i;
  sc_core::sc_in<std::uint32_t> cruise_i, limit_i, exit_i, length_i, brake_exit_i, accel_i, vmin_i, override_i;
  sc_core::sc_in<std::uint64_t> v_x_i, v_y_i, v_z_i, cap_i, cap_z_i;
  sc_core::sc_out<bool> iterate_o;
  sc_core::sc_out<std::uint64_t> speed_o;

  SC_HAS_PROCESS(dda_pace);
  // aw: the integrands' width (the RTL's AW); the other widths are model/motion/pacer.hpp's.
  dda_pace(sc_core::sc_module_name name, int aw);

  // The registers (names as in the RTL); d is the norm unit's.
  sc_core::sc_signal<std::uint64_t> v_q{"v_q"}, ph_q{"ph_q"}, s_q{"s_q"}, rem_q{"rem_q"};
  sc_core::sc_signal<std::uint32_t> cruise_q{"cruise_q"}, limit_q{"limit_q"}, exit_q{"exit_q"}, brake_q{"brake_q"},
      busy_q{"busy_q"};
  sc_core::sc_signal<bool> pend_q{"pend_q"};
  // The cruise speed times the override, by shift and add.
  sc_core::sc_signal<std::uint32_t> ovr_q{"ovr_q"}, mplier_q{"mplier_q"}, mcnt_q{"mcnt_q"};
  sc_core::sc_signal<std::uint64_t> mcand_q{"mcand_q"}, macc_q{"macc_q"}, eff_q{"eff_q"};
  dda_norm u_norm;

 private:
  void comb();
  void seq();
  void multiply();               // the shift-and-add product's step and start
  std::uint64_t target() const;  // the speed the ramp heads for
  bool decel() const;

  sc_core::sc_signal<bool> start_{"start"}, norm_busy_{"norm_busy"};
  sc_core::sc_signal<std::uint64_t> d_{"d"};
};

}  // namespace dda::sc
