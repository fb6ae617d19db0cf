// SPDX-License-Identifier: Apache-2.0
// The motion block's GTKWave save file (docs/dda_motion.gtkw).
#include "model/motion/motion_model.hpp"

namespace dda::motion {

namespace {
// The pacing registers, the pacer's state and its decision.
template <typename Reg>
hw::WaveGroup pace_group(const Reg& reg) {
  return {"Pace",
          {reg("paced_q"),
           reg("feed_hold_q"),
           reg("stopping_q"),
           reg("accel_q"),
           reg("vmin_q"),
           reg("override_q"),
           reg("u_pace.v_q"),
           reg("u_pace.ph_q", true),
           reg("u_pace.s_q"),
           reg("u_pace.rem_q"),
           reg("u_pace.eff_q"),
           reg("u_pace.d_q"),
           reg("u_pace.busy_q"),
           reg("u_pace.pend_q"),
           reg("u_pace.fresh_q"),
           reg("u_pace.m_q"),
           reg("u_pace.cm_q"),
           reg("u_pace.cd_q"),
           {"pace_iterate", 1}}};
}
}  // namespace

std::string gtkw(std::string_view file, std::string_view top, int depth_log2) {
  const auto reg = [&](std::string_view name, bool is_signed = false) {
    return hw::WaveSignal{std::string(name), width_bits(kBlockRegs[breg(name)].width, depth_log2), is_signed};
  };
  std::vector<hw::WaveGroup> g;
  g.push_back({"Bus",
               {{"wb_cyc_i", 1},
                {"wb_stb_i", 1},
                {"wb_we_i", 1},
                {"wb_adr_i", kAddrWidth},
                {"wb_dat_i", 32},
                {"wb_ack_o", 1},
                {"wb_stall_o", 1},
                {"wb_dat_o", 32}}});
  g.push_back({"Queue", {reg("head_q"), reg("tail_q"), reg("level_q"), reg("mask_q"), reg("fetch_q")}});
  g.push_back({"Status",
               {reg("err_q"),
                reg("err_overflow_q"),
                reg("err_partial_q"),
                reg("err_lanes_q"),
                reg("err_stall_q"),
                reg("aborted_q"),
                reg("irq_status_q"),
                reg("irq_enable_q"),
                reg("irq_level_q"),
                {"irq_o", 1}}});
  g.push_back({"Axes",
               {{"step_x_o", 1},
                {"dir_x_o", 1},
                {"step_y_o", 1},
                {"dir_y_o", 1},
                {"step_z_o", 1},
                {"dir_z_o", 1},
                {"busy_o", 1},
                reg("pos_x_q", true),
                reg("pos_y_q", true),
                reg("pos_z_q", true),
                reg("done_count_q"),
                reg("done_wait_q"),
                reg("err_count_q")}});
  g.push_back({"Step/dir and feed",
               {reg("u_sx.step_q"),
                reg("u_sx.dir_q"),
                reg("u_sx.pend_q"),
                reg("u_sx.tf_q"),
                reg("u_sy.step_q"),
                reg("u_sy.dir_q"),
                reg("u_sy.pend_q"),
                reg("u_sy.tf_q"),
                reg("u_sz.step_q"),
                reg("u_sz.dir_q"),
                reg("u_sz.pend_q"),
                reg("u_sz.tf_q"),
                reg("feed_q"),
                reg("acc_q"),
                reg("axes_q"),
                reg("route_q"),
                {"core_ce", 1}}});
  g.push_back(pace_group(reg));
  hw::WaveGroup core{"Core", {}};
  for (const auto& r : hw::kSignals) {
    if (r.kind == hw::SigKind::Reg && (r.group == "Control" || r.group == "Counters")) {
      core.signals.push_back({"u_core." + std::string(r.name), r.width, r.show_signed});
    }
  }
  g.push_back(std::move(core));
  return hw::gtkw_file(g, "the DDA motion block", file, top);
}

}  // namespace dda::motion
