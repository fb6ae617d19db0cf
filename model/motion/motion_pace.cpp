// SPDX-License-Identifier: Apache-2.0
// The motion block's reference model, its pacing (rtl/dda_motion.v, "pace"): the pacer
// (motion::Pacer, rtl/dda_pace.v's u_pace), the pacing settings ACCEL, VMIN, OVERRIDE,
// the feed hold, the soft stop and the watchdog.
#include "model/datapath/hw_params.hpp"
#include "model/motion/motion_model.hpp"
#include "model/motion/motion_wires.hpp"

namespace dda::motion {

NormOperands core_norm_operands(const Signals& s) {
  // (The signals' indices found once: this runs on every edge.)
  static const std::size_t cnt_x = hw::sig("u_cnt_x.cnt_q"), jv_x = hw::sig("u_int_x.jv_q"),
                           cnt_y = hw::sig("u_cnt_y.cnt_q"), jv_y = hw::sig("u_int_y.jv_q"),
                           cnt_z = hw::sig("u_cnt_z.cnt_q"), jv_z = hw::sig("u_lin_z.jv_q"), cap = hw::sig("cap_q"),
                           cap_z = hw::sig("u_lin_z.cap_q");
  const std::uint64_t sign = std::uint64_t{1} << (hw::kAccWidth - 1);
  const auto v = [&](std::size_t cnt, std::size_t jv) { return s[cnt] != 0 && (s[jv] & sign) == 0 ? s[jv] : 0; };
  return NormOperands{v(cnt_x, jv_x), v(cnt_y, jv_y), v(cnt_z, jv_z), s[cap], s[cap_z]};
}

void MotionModel::pace_wires(bool take_known, Wires& w) const {
  Pacer::In& in = w.pace;
  if (!take_known) {
    // What the decision to iterate reads: the pacer runs while the core runs a paced piece.
    in.advance = w.advance;
    in.running = w.running && r_[DDA_BREG("paced_q")] != 0;
    in.stepped = w.stepped;
    w.pace_iterate = pacer_.iterate(in);
    return;
  }
  in.norm = core_norm_operands(core_.state());
  in.take = w.take;
  if (w.cmd_valid) in.entry = entry_pace(mem_[w.head]);
  // Another entry waits in the queue besides the one taken on this edge.
  in.next_queued = w.level > (w.take ? 1u : 0u);
  in.set.accel = r_[DDA_BREG("accel_q")];
  in.set.vmin = std::uint32_t(r_[DDA_BREG("vmin_q")]);
  in.set.override_ = std::uint32_t(r_[DDA_BREG("override_q")]);
  in.set.hold = halt();
}

bool MotionModel::halt() const { return r_[DDA_BREG("feed_hold_q")] != 0 || r_[DDA_BREG("stopping_q")] != 0; }

bool MotionModel::soft_flush() const {
  // No step on its way: none out of the core (the stages' step inputs are the core's
  // step outputs, routed), none waiting in a stage, no pulse out.
  const PortValues p = CoreModel::outputs(core_.state(), false);
  bool busy = false;
  static const std::size_t sx = core_out("step_x_o"), sy = core_out("step_y_o"), sz = core_out("step_z_o");
  busy = busy || p[sx] != 0 || p[sy] != 0 || p[sz] != 0;
  for (const char axis : kAxes) busy = busy || stage(axis).pend || stage(axis).step;
  return r_[DDA_BREG("stopping_q")] != 0 && pacer_.speed() == 0 && !busy;
}

void MotionModel::load_watchdog(const Wires& w) {
  r_[DDA_BREG("stopping_q")] = !w.abort && (r_[DDA_BREG("stopping_q")] != 0 || w.soft_stop || w.bite || w.io_soft);
  if (w.wr && w.adr == DDA_REG_OFFSET("WATCHDOG")) {
    r_[DDA_BREG("wd_q")] = w.wdat;
    r_[DDA_BREG("wd_cnt_q")] = w.wdat;
  } else if (r_[DDA_BREG("wd_cnt_q")] != 0) {
    r_[DDA_BREG("wd_cnt_q")] = r_[DDA_BREG("wd_cnt_q")] - 1;
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
  r_[DDA_BREG("u_pace.v_q")] = pacer_.speed();
  r_[DDA_BREG("u_pace.ph_q")] = pacer_.phase();
  r_[DDA_BREG("u_pace.s_q")] = pacer_.brake();
  r_[DDA_BREG("u_pace.rem_q")] = pacer_.to_go();
  r_[DDA_BREG("u_pace.cruise_q")] = e.cruise;
  r_[DDA_BREG("u_pace.limit_q")] = e.limit;
  r_[DDA_BREG("u_pace.exit_q")] = e.exit;
  r_[DDA_BREG("u_pace.brake_q")] = e.brake_exit;
  r_[DDA_BREG("u_pace.busy_q")] = std::uint64_t(pacer_.norm_busy());
  r_[DDA_BREG("u_pace.pend_q")] = pacer_.pending();
  r_[DDA_BREG("u_pace.first_q")] = pacer_.first();
  r_[DDA_BREG("u_pace.due_q")] = pacer_.due();
  r_[DDA_BREG("u_pace.fresh_q")] = pacer_.fresh();
  r_[DDA_BREG("u_pace.m_q")] = std::uint64_t(pacer_.provisional());
  r_[DDA_BREG("u_pace.cm_q")] = std::uint64_t(pacer_.correction_bits());
  r_[DDA_BREG("u_pace.cd_q")] = pacer_.correction_step();
  r_[DDA_BREG("u_pace.d_q")] = pacer_.distance();
  r_[DDA_BREG("u_pace.ovr_q")] = pacer_.override_of();
  r_[DDA_BREG("u_pace.mcnt_q")] = std::uint64_t(pacer_.override_busy());
  r_[DDA_BREG("u_pace.eff_q")] = pacer_.cruise_speed();
}

void MotionModel::load_pace_settings(const Wires& w) {
  // A feed hold outlasts an abort: a held machine stays held until CTRL.resume.
  const bool ctrl = w.wr && w.adr == DDA_REG_OFFSET("CTRL");
  const auto bit = [&](std::string_view f) { return ctrl && ((w.wsel >> field_of("CTRL", f).lsb) & 1u) != 0; };
  r_[DDA_BREG("feed_hold_q")] = bit("hold") || (r_[DDA_BREG("feed_hold_q")] && !bit("resume"));
  if (!build_.pacer) return;  // ACCEL, VMIN, OVERRIDE keep their reset values
  if (w.wr && w.adr == DDA_REG_OFFSET("ACCEL")) r_[DDA_BREG("accel_q")] = w.wdat;
  if (w.wr && w.adr == DDA_REG_OFFSET("VMIN")) r_[DDA_BREG("vmin_q")] = w.wdat;
  if (w.wr && w.adr == DDA_REG_OFFSET("OVERRIDE"))
    r_[DDA_BREG("override_q")] = std::min<std::uint32_t>(w.wdat, 2 * kOverrideOne);
}

std::uint32_t MotionModel::read_pace(std::uint32_t adr) const {
  if (adr == DDA_REG_OFFSET("ACCEL")) return std::uint32_t(r_[DDA_BREG("accel_q")]);
  if (adr == DDA_REG_OFFSET("VMIN")) return std::uint32_t(r_[DDA_BREG("vmin_q")]);
  if (adr == DDA_REG_OFFSET("OVERRIDE")) return std::uint32_t(r_[DDA_BREG("override_q")]);
  if (adr == DDA_REG_OFFSET("WATCHDOG")) return std::uint32_t(r_[DDA_BREG("wd_q")]);
  if (adr != DDA_REG_OFFSET("STATUS")) return 0;
  const bool hold = r_[DDA_BREG("feed_hold_q")] != 0, at_rest = pacer_.speed() == 0;
  const auto bit = [](std::string_view f, bool v) { return std::uint32_t(v) << field_of("STATUS", f).lsb; };
  return bit("holding", hold && !at_rest) | bit("held", hold && at_rest) |
         bit("stopping", r_[DDA_BREG("stopping_q")] != 0) | bit("err_hard_stop", r_[DDA_BREG("err_hard_q")] != 0) |
         bit("err_watchdog", r_[DDA_BREG("err_watchdog_q")] != 0);
}

}  // namespace dda::motion
