// SPDX-License-Identifier: Apache-2.0
// The motion block's reference model, its pacing (rtl/dda_motion.v, "pace"): the pacer
// (motion::Pacer, rtl/dda_pace.v's u_pace), the pacing settings ACCEL, VMIN, OVERRIDE,
// the feed hold, the soft stop and the watchdog.
#include "model/datapath/hw_params.hpp"
#include "model/motion/motion_model.hpp"
#include "model/motion/motion_wires.hpp"

namespace dda::motion {

NormOperands core_norm_operands(const Signals& s) {
  const auto reg = [&](std::string_view name) { return s[hw::sig(name)]; };
  const std::uint64_t sign = std::uint64_t{1} << (hw::kAccWidth - 1);
  const auto v = [&](std::string_view cnt, std::string_view jv) {
    return reg(cnt) != 0 && (reg(jv) & sign) == 0 ? reg(jv) : 0;
  };
  return NormOperands{v("u_cnt_x.cnt_q", "u_int_x.jv_q"), v("u_cnt_y.cnt_q", "u_int_y.jv_q"),
                      v("u_cnt_z.cnt_q", "u_lin_z.jv_q"), reg("cap_q"), reg("u_lin_z.cap_q")};
}

void MotionModel::pace_wires(bool take_known, Wires& w) const {
  Pacer::In& in = w.pace;
  if (!take_known) {
    // What the decision to iterate reads: the pacer runs while the core runs a paced piece.
    in.advance = w.advance;
    in.running = w.running && get("paced_q") != 0;
    in.stepped = w.stepped;
    w.pace_iterate = pacer_.iterate(in);
    return;
  }
  in.norm = core_norm_operands(core_.state());
  in.take = w.take;
  if (w.cmd_valid) in.entry = entry_pace(mem_[w.head]);
  // Another entry waits in the queue besides the one taken on this edge.
  in.next_queued = w.level > (w.take ? 1u : 0u);
  in.set.accel = get("accel_q");
  in.set.vmin = std::uint32_t(get("vmin_q"));
  in.set.override_ = std::uint32_t(get("override_q"));
  in.set.hold = halt();
}

bool MotionModel::halt() const { return get("feed_hold_q") != 0 || get("stopping_q") != 0; }

bool MotionModel::soft_flush() const {
  // No step on its way: none out of the core (the stages' step inputs are the core's
  // step outputs, routed), none waiting in a stage, no pulse out.
  const PortValues p = CoreModel::outputs(core_.state(), false);
  bool busy = false;
  for (const char* o : {"step_x_o", "step_y_o", "step_z_o"}) busy = busy || p[core_out(o)] != 0;
  for (const char axis : kAxes) busy = busy || stage(axis).pend || stage(axis).step;
  return get("stopping_q") != 0 && pacer_.speed() == 0 && !busy;
}

void MotionModel::load_watchdog(const Wires& w) {
  reg("stopping_q") = !w.abort && (get("stopping_q") != 0 || w.soft_stop || w.bite || w.io_soft);
  if (w.wr && w.adr == reg_offset("WATCHDOG")) {
    reg("wd_q") = w.wdat;
    reg("wd_cnt_q") = w.wdat;
  } else if (get("wd_cnt_q") != 0) {
    reg("wd_cnt_q") = get("wd_cnt_q") - 1;
  }
}

void MotionModel::load_pace(const Wires& w) {
  // The pacer's reset is the core's: a reset or an abort; not built, it is held in reset.
  if (w.abort || !build_.pacer) {
    pacer_ = Pacer{};
  } else {
    pacer_.edge(w.pace);
  }
  const PaceEntry& e = pacer_.entry();
  reg("u_pace.v_q") = pacer_.speed();
  reg("u_pace.ph_q") = pacer_.phase();
  reg("u_pace.s_q") = pacer_.brake();
  reg("u_pace.rem_q") = pacer_.to_go();
  reg("u_pace.cruise_q") = e.cruise;
  reg("u_pace.limit_q") = e.limit;
  reg("u_pace.exit_q") = e.exit;
  reg("u_pace.brake_q") = e.brake_exit;
  reg("u_pace.busy_q") = std::uint64_t(pacer_.norm_busy());
  reg("u_pace.pend_q") = pacer_.pending();
  reg("u_pace.first_q") = pacer_.first();
  reg("u_pace.due_q") = pacer_.due();
  reg("u_pace.fresh_q") = pacer_.fresh();
  reg("u_pace.m_q") = std::uint64_t(pacer_.provisional());
  reg("u_pace.cm_q") = std::uint64_t(pacer_.correction_bits());
  reg("u_pace.cd_q") = pacer_.correction_step();
  reg("u_pace.d_q") = pacer_.distance();
  reg("u_pace.ovr_q") = pacer_.override_of();
  reg("u_pace.mcnt_q") = std::uint64_t(pacer_.override_busy());
  reg("u_pace.eff_q") = pacer_.cruise_speed();
}

void MotionModel::load_pace_settings(const Wires& w) {
  // A feed hold outlasts an abort: a held machine stays held until CTRL.resume.
  const bool ctrl = w.wr && w.adr == reg_offset("CTRL");
  const auto bit = [&](std::string_view f) { return ctrl && ((w.wsel >> field_of("CTRL", f).lsb) & 1u) != 0; };
  reg("feed_hold_q") = bit("hold") || (get("feed_hold_q") && !bit("resume"));
  if (!build_.pacer) return;  // ACCEL, VMIN, OVERRIDE keep their reset values
  if (w.wr && w.adr == reg_offset("ACCEL")) reg("accel_q") = w.wdat;
  if (w.wr && w.adr == reg_offset("VMIN")) reg("vmin_q") = w.wdat;
  if (w.wr && w.adr == reg_offset("OVERRIDE")) reg("override_q") = std::min<std::uint32_t>(w.wdat, 2 * kOverrideOne);
}

std::uint32_t MotionModel::read_pace(std::uint32_t adr) const {
  if (adr == reg_offset("ACCEL")) return std::uint32_t(get("accel_q"));
  if (adr == reg_offset("VMIN")) return std::uint32_t(get("vmin_q"));
  if (adr == reg_offset("OVERRIDE")) return std::uint32_t(get("override_q"));
  if (adr == reg_offset("WATCHDOG")) return std::uint32_t(get("wd_q"));
  if (adr != reg_offset("STATUS")) return 0;
  const bool hold = get("feed_hold_q") != 0, at_rest = pacer_.speed() == 0;
  const auto bit = [](std::string_view f, bool v) { return std::uint32_t(v) << field_of("STATUS", f).lsb; };
  return bit("holding", hold && !at_rest) | bit("held", hold && at_rest) | bit("stopping", get("stopping_q") != 0) |
         bit("err_hard_stop", get("err_hard_q") != 0) | bit("err_watchdog", get("err_watchdog_q") != 0);
}

}  // namespace dda::motion
