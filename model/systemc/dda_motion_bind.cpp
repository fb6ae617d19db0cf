// SPDX-License-Identifier: Apache-2.0
// The SystemC motion block's submodules bound to its wires: the step/dir stages, the
// pacer and the machine side (u_io), with the wires u_io takes.
#include "model/systemc/dda_motion.hpp"

namespace dda::sc {

void dda_motion::bind_stages() {
  struct Stage {
    dda_stepdir& s;
    sc_core::sc_signal<bool>&step, &dir, &out_step, &out_dir, &hold, &rise, &rise_dir, &wait, &tag_left, &busy, &pend,
        &pdir;
    sc_core::sc_signal<std::uint32_t>&steplen, &stepspace, &dirsetup, &dirhold;
  };
  for (Stage t : {Stage{u_sx, step_x, dir_x, stw.sx_step, stw.sx_dir, stw.sx_hold, stw.sx_rise, stw.sx_rise_dir,
                        stw.sx_wait, stw.sx_tag_left, stw.sx_busy, stw.sx_pend, stw.sx_pdir, steplen_x_q, stepspace_x_q,
                        dirsetup_x_q, dirhold_x_q},
                  Stage{u_sy, step_y, dir_y, stw.sy_step, stw.sy_dir, stw.sy_hold, stw.sy_rise, stw.sy_rise_dir,
                        stw.sy_wait, stw.sy_tag_left, stw.sy_busy, stw.sy_pend, stw.sy_pdir, steplen_y_q, stepspace_y_q,
                        dirsetup_y_q, dirhold_y_q},
                  Stage{u_sz, step_z, dir_z, stw.sz_step, stw.sz_dir, stw.sz_hold, stw.sz_rise, stw.sz_rise_dir,
                        stw.sz_wait, stw.sz_tag_left, stw.sz_busy, stw.sz_pend, stw.sz_pdir, steplen_z_q, stepspace_z_q,
                        dirsetup_z_q, dirhold_z_q}}) {
    t.s.clk_i(clk_i);
    const bool built = &t.s != &u_sz || build_.axes == 3;  // (2 axes: Z's stage held in reset)
    if (built)
      t.s.rst_ni(rst_ni);
    else
      t.s.rst_ni(off);
    t.s.flush_i(flush);
    t.s.step_i(t.step);
    t.s.dir_i(t.dir);
    if (built)
      t.s.tag_i(core_done);
    else
      t.s.tag_i(off);
    t.s.steplen_i(t.steplen);
    t.s.stepspace_i(t.stepspace);
    t.s.dirsetup_i(t.dirsetup);
    t.s.dirhold_i(t.dirhold);
    t.s.step_o(t.out_step);
    t.s.dir_o(t.out_dir);
    t.s.hold_o(t.hold);
    t.s.rise_o(t.rise);
    t.s.rise_dir_o(t.rise_dir);
    t.s.wait_o(t.wait);
    t.s.tag_left_o(t.tag_left);
    t.s.busy_o(t.busy);
    t.s.pend_o(t.pend);
    t.s.pdir_o(t.pdir);
  }
}

void dda_motion::bind_pace() {
  u_pace.clk_i(clk_i);
  u_pace.rst_ni(pace_rst_n);  // the core's reset (a reset or an abort), or held (no pacer)
  u_pace.advance_i(advance);
  u_pace.running_i(pace_running);
  u_pace.take_i(take);
  u_pace.cruise_i(entry_pace[0]);
  u_pace.limit_i(entry_pace[1]);
  u_pace.exit_i(entry_pace[2]);
  u_pace.length_i(entry_pace[3]);
  u_pace.brake_exit_i(entry_pace[4]);
  u_pace.next_queued_i(next_queued);
  u_pace.accel_i(accel_q);
  u_pace.vmin_i(vmin_q);
  u_pace.override_i(override_q);
  u_pace.hold_i(pace_halt);
  u_pace.stepped_i(stepped);
  u_pace.v_x_i(norm_v_x);
  u_pace.v_y_i(norm_v_y);
  u_pace.v_z_i(norm_v_z);
  u_pace.cap_i(norm_cap);
  u_pace.cap_z_i(norm_cap_z);
  u_pace.iterate_o(pace_iterate);
  u_pace.speed_o(pace_speed);
}

void dda_motion::bind_io() {
  u_io.clk_i(clk_i);
  u_io.rst_ni(io_rst_n);
  u_io.estop_ni(estop_ni);
  u_io.limit_i(limit_i);
  u_io.home_i(home_i);
  u_io.probe_i(probe_i);
  u_io.wr_i(iow.io_wr);
  u_io.adr_i(iow.io_adr);
  u_io.wdat_i(iow.io_wdat);
  u_io.clear_i(iow.io_clear);
  u_io.snapshot_i(iow.io_snapshot);
  u_io.probe_arm_i(iow.io_probe_arm);
  u_io.pos_x_i(pos_x_q);
  u_io.pos_y_i(pos_y_q);
  u_io.pos_z_i(pos_z_q);
  u_io.level_i(level_q);
  u_io.done_count_i(done_count_q);
  u_io.step_i(iow.io_step);
  u_io.dir_i(iow.io_dir);
  u_io.pend_i(iow.io_pend);
  u_io.pdir_i(iow.io_pdir);
  u_io.hard_o(iow.io_hard);
  u_io.soft_o(iow.io_soft);
  u_io.err_o(iow.io_err);
  u_io.probe_o(iow.io_probe);
  u_io.home_o(iow.io_home);
  u_io.err_estop_o(iow.io_err_estop);
  u_io.err_limit_o(iow.io_err_limit);
  u_io.probe_armed_o(iow.io_probe_armed);
  u_io.probed_o(iow.io_probed);
  u_io.rd_o(iow.io_rd);
}

// u_io's inputs of this cycle: the bus write (its data merged with the addressed
// register's value in the lanes not selected), the CTRL bits, the routed steps of the
// core and the steps waiting in the stages (bit j: stage j).
void dda_motion::comb_io(bool wr, std::uint32_t adr, std::uint32_t wsel, std::uint32_t lanes, std::uint32_t r_step,
                         std::uint32_t r_dir) {
  const bool ctrl = wr && adr == motion::reg_offset("CTRL");
  const auto bit = [&](std::string_view f) { return ctrl && ((wsel >> motion::field_of("CTRL", f).lsb) & 1u) != 0; };
  iow.io_wr.write(wr);
  iow.io_adr.write(adr);
  iow.io_wdat.write(wr ? (read(adr) & ~lanes) | wsel : 0u);
  iow.io_clear.write(bit("clear"));
  iow.io_snapshot.write(bit("snapshot"));
  iow.io_probe_arm.write(bit("probe_arm"));
  iow.io_step.write(r_step);
  iow.io_dir.write(r_dir);
  iow.io_pend.write(std::uint32_t(stw.sx_pend.read()) | std::uint32_t(stw.sy_pend.read()) << 1 |
                    std::uint32_t(stw.sz_pend.read()) << 2);
  iow.io_pdir.write(std::uint32_t(stw.sx_pdir.read()) | std::uint32_t(stw.sy_pdir.read()) << 1 |
                    std::uint32_t(stw.sz_pdir.read()) << 2);
}

}  // namespace dda::sc
