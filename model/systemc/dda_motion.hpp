// SPDX-License-Identifier: Apache-2.0
// SystemC model of the motion block: same ports, registers and hierarchy as
// rtl/dda_motion.v (docs/design.md, "Motion block"), around the SystemC model of the
// core. Register for register: a co-simulation names the register and the cycle where
// the two differ. The queue memory is a plain array of entries; `rd_row_q` holds the row
// of the head entry read on the last edge (the RTL's block-RAM output registers),
// `row0_q` the row 0 kept from the edge before.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/motion/build.hpp"
#include "model/motion/motion_map.hpp"
#include "model/systemc/dda_core.hpp"
#include "model/systemc/dda_motion_io.hpp"
#include "model/systemc/dda_pace.hpp"
#include "model/systemc/dda_stepdir.hpp"

namespace dda::sc {

// The outputs of the step/dir stages (u_sx, u_sy, u_sz).
struct StageWires {
  sc_core::sc_signal<bool> sx_step{"sx_step"}, sx_dir{"sx_dir"}, sx_hold{"sx_hold"}, sx_rise{"sx_rise"},
      sx_rise_dir{"sx_rise_dir"}, sx_wait{"sx_wait"}, sx_tag_left{"sx_tag_left"}, sx_busy{"sx_busy"};
  sc_core::sc_signal<bool> sy_step{"sy_step"}, sy_dir{"sy_dir"}, sy_hold{"sy_hold"}, sy_rise{"sy_rise"},
      sy_rise_dir{"sy_rise_dir"}, sy_wait{"sy_wait"}, sy_tag_left{"sy_tag_left"}, sy_busy{"sy_busy"};
  sc_core::sc_signal<bool> sz_step{"sz_step"}, sz_dir{"sz_dir"}, sz_hold{"sz_hold"}, sz_rise{"sz_rise"},
      sz_rise_dir{"sz_rise_dir"}, sz_wait{"sz_wait"}, sz_tag_left{"sz_tag_left"}, sz_busy{"sz_busy"};
  sc_core::sc_signal<bool> sx_pend{"sx_pend"}, sx_pdir{"sx_pdir"}, sy_pend{"sy_pend"}, sy_pdir{"sy_pdir"},
      sz_pend{"sz_pend"}, sz_pdir{"sz_pdir"};
};

// The wires of the block's machine side: u_io's inputs (dda_motion::comb_io) and outputs.
struct MotionIoWires {
  sc_core::sc_signal<bool> io_wr{"io_wr"}, io_clear{"io_clear"}, io_snapshot{"io_snapshot"},
      io_probe_arm{"io_probe_arm"};
  sc_core::sc_signal<std::uint32_t> io_adr{"io_adr"}, io_wdat{"io_wdat"}, io_step{"io_step"}, io_dir{"io_dir"},
      io_pend{"io_pend"}, io_pdir{"io_pdir"}, io_rd{"io_rd"};
  sc_core::sc_signal<bool> io_hard{"io_hard"}, io_soft{"io_soft"}, io_err{"io_err"}, io_probe{"io_probe"},
      io_home{"io_home"}, io_err_estop{"io_err_estop"}, io_err_limit{"io_err_limit"}, io_probe_armed{"io_probe_armed"},
      io_probed{"io_probed"};
};

SC_MODULE(dda_motion) {
  sc_core::sc_in<bool> clk_i, rst_ni;
  sc_core::sc_in<bool> wb_cyc_i, wb_stb_i, wb_we_i;
  sc_core::sc_in<std::uint32_t> wb_adr_i, wb_dat_i, wb_sel_i;
  sc_core::sc_out<std::uint32_t> wb_dat_o;
  sc_core::sc_out<bool> wb_ack_o, wb_stall_o;
  sc_core::sc_in<bool> ce_i;
  sc_core::sc_in<bool> estop_ni, probe_i;
  sc_core::sc_in<std::uint32_t> limit_i, home_i;  // limit_i[5:0], home_i[2:0]
  sc_core::sc_out<bool> step_x_o, step_y_o, dir_x_o, dir_y_o, step_z_o, dir_z_o, busy_o, irq_o;

  SC_HAS_PROCESS(dda_motion);
  // The build-time choices (motion::Build, model/motion/build.hpp) as rtl/dda_motion.v's
  // parameters: without the inputs, u_io is held in reset.
  dda_motion(sc_core::sc_module_name name, const motion::Build& build);

  dda_core u_core{"u_core"};
  dda_stepdir u_sx{"u_sx"}, u_sy{"u_sy"}, u_sz{"u_sz"};
  dda_pace u_pace{"u_pace", hw::kAccWidth};
  dda_motion_io u_io;

  // The block's registers (names and widths as in the RTL and motion::kBlockRegs).
  sc_core::sc_signal<bool> ack_q{"ack_q"}, done_wait_q{"done_wait_q"}, err_q{"err_q"}, err_overflow_q{"err_overflow_q"},
      err_partial_q{"err_partial_q"}, err_stall_q{"err_stall_q"}, aborted_q{"aborted_q"}, err_lanes_q{"err_lanes_q"};
  sc_core::sc_signal<std::uint32_t> dat_q{"dat_q"}, head_q{"head_q"}, tail_q{"tail_q"}, level_q{"level_q"},
      mask_q{"mask_q"}, irq_status_q{"irq_status_q"}, irq_enable_q{"irq_enable_q"}, irq_level_q{"irq_level_q"},
      done_count_q{"done_count_q"}, err_count_q{"err_count_q"}, pos_x_q{"pos_x_q"}, pos_y_q{"pos_y_q"},
      pos_z_q{"pos_z_q"}, fetch_q{"fetch_q"}, steplen_z_q{"steplen_z_q"}, stepspace_z_q{"stepspace_z_q"},
      dirsetup_z_q{"dirsetup_z_q"}, dirhold_z_q{"dirhold_z_q"}, axes_q{"axes_q"}, route_q{"route_q"}, feed_q{"feed_q"},
      acc_q{"acc_q"}, steplen_x_q{"steplen_x_q"}, stepspace_x_q{"stepspace_x_q"}, dirsetup_x_q{"dirsetup_x_q"},
      dirhold_x_q{"dirhold_x_q"}, steplen_y_q{"steplen_y_q"}, stepspace_y_q{"stepspace_y_q"},
      dirsetup_y_q{"dirsetup_y_q"}, dirhold_y_q{"dirhold_y_q"}, polarity_q{"polarity_q"};
  // Pacing: the running entry has a cruise speed; the feed hold and the settings.
  sc_core::sc_signal<bool> paced_q{"paced_q"}, feed_hold_q{"feed_hold_q"}, stopping_q{"stopping_q"};
  sc_core::sc_signal<std::uint32_t> accel_q{"accel_q"}, vmin_q{"vmin_q"}, override_q{"override_q"};
  // The watchdog (timeout, count) and the sticky causes of the stops.
  sc_core::sc_signal<std::uint32_t> wd_q{"wd_q"}, wd_cnt_q{"wd_cnt_q"};
  sc_core::sc_signal<bool> err_hard_q{"err_hard_q"}, err_watchdog_q{"err_watchdog_q"};

 private:
  motion::Build build_;
  int depth_log2_;
  std::vector<std::vector<std::uint32_t>> mem_;
  std::vector<std::uint32_t> rd_row_q, row0_q;  // the RAM output and the row 0 kept (words)
  sc_core::sc_signal<cmd_t> entry{"entry"};     // the command of {rd_row_q, row0_q}
  sc_core::sc_signal<std::uint32_t> entry_feed{"entry_feed"}, entry_axes{"entry_axes"};
  std::array<sc_core::sc_signal<std::uint32_t>, motion::kPaceWords> entry_pace;  // motion::kPaceFields' order
  // Wires: the pacer's, the core's, the stages'.
  sc_core::sc_signal<bool> advance{"advance"}, pace_running{"pace_running"}, take{"take"}, next_queued{"next_queued"},
      stepped{"stepped"}, pace_iterate{"pace_iterate"}, pace_halt{"pace_halt"};
  sc_core::sc_signal<std::uint64_t> norm_v_x{"norm_v_x"}, norm_v_y{"norm_v_y"}, norm_v_z{"norm_v_z"},
      norm_cap{"norm_cap"}, norm_cap_z{"norm_cap_z"}, pace_speed{"pace_speed"};
  sc_core::sc_signal<bool> io_rst_n{"io_rst_n"};      // u_io's reset
  sc_core::sc_signal<bool> pace_rst_n{"pace_rst_n"};  // u_pace's reset
  sc_core::sc_signal<bool> off{"off"};                // never written: the reset and tag of a stage not built
  sc_core::sc_signal<bool> core_rst_n{"core_rst_n"}, cmd_valid{"cmd_valid"}, core_ready{"core_ready"};
  sc_core::sc_signal<bool> core_busy{"core_busy"}, core_done{"core_done"}, core_err{"core_err"}, core_iter{"core_iter"};
  sc_core::sc_signal<bool> step_x{"step_x"}, step_y{"step_y"}, dir_x{"dir_x"}, dir_y{"dir_y"};
  sc_core::sc_signal<bool> step_z{"step_z"}, dir_z{"dir_z"};  // the core's axes routed to the stages (route_q)
  sc_core::sc_signal<bool> c_step_x{"c_step_x"}, c_step_y{"c_step_y"}, c_step_z{"c_step_z"}, c_dir_x{"c_dir_x"},
      c_dir_y{"c_dir_y"}, c_dir_z{"c_dir_z"};                                 // the core's step outputs
  sc_core::sc_signal<bool> core_ce{"core_ce"}, flush{"flush"}, hold{"hold"};  // flush: the abort of this cycle
  StageWires stw;                                                             // the step/dir stages' outputs
  MotionIoWires iow;                                                          // u_io's wires

  // The timing registers in motion::kTimingFields' order, X's, Y's then Z's.
  std::array<sc_core::sc_signal<std::uint32_t>*, 12> timing_regs() const;
  void bind_stages();
  void bind_pace();
  void bind_io();
  void comb_io(bool wr, std::uint32_t adr, std::uint32_t wsel, std::uint32_t lanes, std::uint32_t r_step,
               std::uint32_t r_dir);
  void comb();
  void seq();
  std::uint32_t read(std::uint32_t adr) const;
  struct Decode;  // seq() in parts (dda_motion.cpp)
  Decode decode() const;
  void seq_ram(const Decode& d);
  void seq_reset();
  void seq_bus(const Decode& d);
  void seq_queue(const Decode& d);
  void seq_status(const Decode& d);
  void seq_feed(const Decode& d);
  void seq_settings(const Decode& d);
  void seq_pace_settings(const Decode& d);  // feed_hold_q, accel_q, vmin_q, override_q, stopping_q, the watchdog
};

}  // namespace dda::sc
