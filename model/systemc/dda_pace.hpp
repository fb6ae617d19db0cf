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

  // The registers (names as in the RTL); d_ is the norm unit's last d.
  sc_core::sc_signal<std::uint64_t> v_q{"v_q"}, ph_q{"ph_q"}, s_q{"s_q"}, rem_q{"rem_q"};
  sc_core::sc_signal<std::uint32_t> cruise_q{"cruise_q"}, limit_q{"limit_q"}, exit_q{"exit_q"}, brake_q{"brake_q"},
      busy_q{"busy_q"};
  sc_core::sc_signal<bool> pend_q{"pend_q"}, first_q{"first_q"}, due_q{"due_q"}, fresh_q{"fresh_q"};
  sc_core::sc_signal<std::uint32_t> m_q{"m_q"};  // the run's provisional iterations
  // The correction, a bit of m per clock: the bits still to apply, and the difference of
  // the d's shifting up (kCorrectionWidth bits, two's complement).
  sc_core::sc_signal<std::uint32_t> cm_q{"cm_q"};
  sc_core::sc_signal<std::uint64_t> cd_q{"cd_q"};
  sc_core::sc_signal<std::uint64_t> d_q{"d_q"};  // the d the pacer paces with
  // (ph_q holds the signed phase in kPhaseWidth bits, two's complement, as the RTL.)
  // The cruise speed times the override, by shift and add (the override's top bit first).
  sc_core::sc_signal<std::uint32_t> ovr_q{"ovr_q"}, mplier_q{"mplier_q"}, mcnt_q{"mcnt_q"};
  sc_core::sc_signal<std::uint64_t> macc_q{"macc_q"}, eff_q{"eff_q"};
  dda_norm u_norm;

 private:
  void comb();
  void seq();
  void reset();
  void norm_seq(bool it);        // the norm unit's count and the hand-over of its d
  void ramp_seq();               // the ramp and the braking distance
  void multiply();               // the shift-and-add product's step and start
  std::uint64_t target() const;  // the speed the ramp heads for
  bool decel() const;
  bool seen() const { return pend_q.read() && stepped_i.read(); }  // a step on the last edge
  bool free() const { return busy_q.read() == 0; }
  bool load() const { return free() && !fresh_q.read(); }  // d_q takes the norm unit's d
  std::int64_t phase() const;                              // ph_q's value
  std::int64_t correction_part() const;                    // this clock's part of the correction

  sc_core::sc_signal<bool> start_{"start"}, norm_busy_{"norm_busy"};
  sc_core::sc_signal<std::uint64_t> d_{"d"};
};

}  // namespace dda::sc
