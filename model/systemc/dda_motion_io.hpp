// SPDX-License-Identifier: Apache-2.0
// SystemC model of the motion block's machine side (rtl/dda_motion_io.v): the E-stop,
// limit, home and probe inputs (dda_input each), the stops they make, the trip, probe
// and snapshot latches and the cycle counter. Same ports, registers and instances.
#pragma once

#include <systemc>

#include <array>
#include <cstdint>
#include <memory>

#include "model/motion/build.hpp"
#include "model/motion/motion_map.hpp"
#include "model/systemc/dda_input.hpp"

namespace dda::sc {

SC_MODULE(dda_motion_io) {
  sc_core::sc_in<bool> clk_i, rst_ni, estop_ni, probe_i;
  sc_core::sc_in<std::uint32_t> limit_i, home_i;  // limit_i[5:0], home_i[2:0]
  sc_core::sc_in<bool> wr_i, clear_i, snapshot_i, probe_arm_i;
  sc_core::sc_in<std::uint32_t> adr_i, wdat_i, pos_x_i, pos_y_i, pos_z_i, level_i, done_count_i;
  sc_core::sc_in<std::uint32_t> step_i, dir_i, pend_i, pdir_i;  // per stage, bit j: stage j
  sc_core::sc_out<bool> hard_o, soft_o, err_o, probe_o, home_o, err_estop_o, err_limit_o, probe_armed_o, probed_o;
  sc_core::sc_out<std::uint32_t> rd_o;

  SC_HAS_PROCESS(dda_motion_io);
  // The build (motion::Build): with 2 axes the Z limits and home are held in reset.
  dda_motion_io(sc_core::sc_module_name name, const motion::Build& build);

  // The registers (names as in the RTL and motion::kBlockRegs below u_io).
  sc_core::sc_signal<std::uint32_t> pol_q{"pol_q"}, filt_sw_q{"filt_sw_q"}, filt_tick_q{"filt_tick_q"},
      filt_probe_q{"filt_probe_q"}, mode_q{"mode_q"}, trip_q{"trip_q"}, latch_x_q{"latch_x_q"}, latch_y_q{"latch_y_q"},
      latch_z_q{"latch_z_q"}, probe_x_q{"probe_x_q"}, probe_y_q{"probe_y_q"}, probe_z_q{"probe_z_q"},
      snap_x_q{"snap_x_q"}, snap_y_q{"snap_y_q"}, snap_z_q{"snap_z_q"}, snap_cycle_q{"snap_cycle_q"},
      snap_level_q{"snap_level_q"}, snap_done_q{"snap_done_q"}, cycle_q{"cycle_q"};
  sc_core::sc_signal<bool> err_estop_q{"err_estop_q"}, err_limit_q{"err_limit_q"}, probe_armed_q{"probe_armed_q"},
      probed_q{"probed_q"};

 private:
  // The inputs in motion::kInputs' order, named by its instances (u_estop, u_lxn, ...).
  std::array<std::unique_ptr<dda_input>, motion::kInputs.size()> in_;
  std::array<sc_core::sc_signal<bool>, motion::kInputs.size()> pin_, invert_, lvl_, rise_;
  sc_core::sc_signal<bool> off_{"off"};  // never written: the reset of an input not built
  // The filters' ticks: the switches' (IN_FILTER.tick of the cycle count), the probe's
  // on every clock.
  sc_core::sc_signal<bool> sw_tick_{"sw_tick"}, every_{"every"};
  // The wires of this cycle (the RTL's): the stops, causes and events.
  struct Wires {
    std::uint32_t lvl = 0, limit_hits = 0, home_ev = 0, trip_now = 0;
    bool estop = false, limit_hit = false, probe_ev = false;
  };
  Wires wires() const;
  std::uint32_t read(std::uint32_t adr) const;
  void comb_pins();
  void comb_tick();
  void comb();
  void seq();
};

}  // namespace dda::sc
