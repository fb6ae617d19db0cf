// SPDX-License-Identifier: Apache-2.0
// The pacer's SystemC model (model/systemc/dda_pace.hpp) and its RTL (rtl/dda_pace.v,
// Verilator) on the same inputs, the reference model's while it paces the golden
// datapath (tb/measure/pace_report.hpp, clock by clock, with a hold and overrides of 100%,
// 0 (the speed sits on the minimum), 50% and 200%): the
// decision on every clock and every register after every edge, the pacer's and its norm
// unit's, a difference named with its register and clock.
#define CATCH_CONFIG_RUNNER
// The verilated model first: verilated.h takes SystemC's time if <systemc> came before it.
#include "Vdda_pace.h"
#include "Vdda_pace___024root.h"
// (then SystemC)
#include <systemc>

#include <catch2/catch.hpp>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "host/planner/planner.hpp"
#include "model/systemc/dda_pace.hpp"
#include "tb/measure/pace_report.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

using namespace dda;
using namespace dda::motion;

namespace {

struct Bench {
  sc_core::sc_signal<bool> clk{"clk"}, rst_n{"rst_n"}, advance{"advance"}, running{"running"}, take{"take"},
      next_queued{"next_queued"}, hold{"hold"}, stepped{"stepped"}, iterate{"iterate"};
  sc_core::sc_signal<std::uint32_t> cruise{"cruise"}, limit{"limit"}, exit{"exit"}, length{"length"},
      brake_exit{"brake_exit"}, accel{"accel"}, vmin{"vmin"}, override_{"override"};
  sc_core::sc_signal<std::uint64_t> vx{"vx"}, vy{"vy"}, vz{"vz"}, cap{"cap"}, cap_z{"cap_z"}, speed{"speed"};
  sc::dda_pace m{"pace", hw::kAccWidth};
  std::unique_ptr<Vdda_pace> rtl = std::make_unique<Vdda_pace>();
  std::uint64_t clock = 0;

  Bench() {
    m.clk_i(clk);
    m.rst_ni(rst_n);
    m.advance_i(advance);
    m.running_i(running);
    m.take_i(take);
    m.next_queued_i(next_queued);
    m.hold_i(hold);
    m.stepped_i(stepped);
    m.cruise_i(cruise);
    m.limit_i(limit);
    m.exit_i(exit);
    m.length_i(length);
    m.brake_exit_i(brake_exit);
    m.accel_i(accel);
    m.vmin_i(vmin);
    m.override_i(override_);
    m.v_x_i(vx);
    m.v_y_i(vy);
    m.v_z_i(vz);
    m.cap_i(cap);
    m.cap_z_i(cap_z);
    m.iterate_o(iterate);
    m.speed_o(speed);
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
    rst_n.write(false);
    rtl->rst_ni = 0;
    edge();
    rst_n.write(true);
    rtl->rst_ni = 1;
  }
  void inputs(const Pacer::In& in) {
    Vdda_pace& t = *rtl;
    t.advance_i = in.advance, advance.write(in.advance);
    t.running_i = in.running, running.write(in.running);
    t.take_i = in.take, take.write(in.take);
    t.cruise_i = in.entry.cruise, cruise.write(in.entry.cruise);
    t.limit_i = in.entry.limit, limit.write(in.entry.limit);
    t.exit_i = in.entry.exit, exit.write(in.entry.exit);
    t.length_i = in.entry.length, length.write(in.entry.length);
    t.brake_exit_i = in.entry.brake_exit, brake_exit.write(in.entry.brake_exit);
    t.next_queued_i = in.next_queued, next_queued.write(in.next_queued);
    t.accel_i = std::uint32_t(in.set.accel), accel.write(std::uint32_t(in.set.accel));
    t.vmin_i = in.set.vmin, vmin.write(in.set.vmin);
    t.override_i = in.set.override_, override_.write(in.set.override_);
    t.hold_i = in.set.hold, hold.write(in.set.hold);
    t.stepped_i = in.stepped, stepped.write(in.stepped);
    const NormOperands& o = in.norm;
    t.v_x_i = o.v_x, vx.write(o.v_x);
    t.v_y_i = o.v_y, vy.write(o.v_y);
    t.v_z_i = o.v_z, vz.write(o.v_z);
    t.cap_i = o.cap, cap.write(o.cap);
    t.cap_z_i = o.cap_z, cap_z.write(o.cap_z);
  }
  void edge() {
    rtl->clk_i = 0;
    rtl->eval();
    clk.write(false);
    sc_core::sc_start(1, sc_core::SC_NS);
    if (bool(rtl->iterate_o) != iterate.read())
      FAIL("clock " << clock << ": iterate_o rtl " << int(rtl->iterate_o) << ", SystemC " << iterate.read());
    rtl->clk_i = 1;
    rtl->eval();
    clk.write(true);
    sc_core::sc_start(1, sc_core::SC_NS);
    ++clock;
  }
  void compare() {
    const auto& r = *rtl->rootp;
    const auto& n = m.u_norm;
    struct Reg {
      const char* name;
      std::uint64_t rtl, sc;
    };
    const std::vector<Reg> regs = {
        {"v_q", r.dda_pace__DOT__v_q, m.v_q.read()},
        {"ph_q", r.dda_pace__DOT__ph_q, m.ph_q.read()},
        {"s_q", r.dda_pace__DOT__s_q, m.s_q.read()},
        {"rem_q", r.dda_pace__DOT__rem_q, m.rem_q.read()},
        {"cruise_q", r.dda_pace__DOT__cruise_q, m.cruise_q.read()},
        {"limit_q", r.dda_pace__DOT__limit_q, m.limit_q.read()},
        {"exit_q", r.dda_pace__DOT__exit_q, m.exit_q.read()},
        {"brake_q", r.dda_pace__DOT__brake_q, m.brake_q.read()},
        {"busy_q", r.dda_pace__DOT__busy_q, m.busy_q.read()},
        {"pend_q", r.dda_pace__DOT__pend_q, m.pend_q.read()},
        {"first_q", r.dda_pace__DOT__first_q, m.first_q.read()},
        {"due_q", r.dda_pace__DOT__due_q, m.due_q.read()},
        {"fresh_q", r.dda_pace__DOT__fresh_q, m.fresh_q.read()},
        {"m_q", r.dda_pace__DOT__m_q, m.m_q.read()},
        {"cm_q", r.dda_pace__DOT__cm_q, m.cm_q.read()},
        {"cd_q", r.dda_pace__DOT__cd_q, m.cd_q.read()},
        {"d_q", r.dda_pace__DOT__d_q, m.d_q.read()},
        {"ovr_q", r.dda_pace__DOT__ovr_q, m.ovr_q.read()},
        {"mplier_q", r.dda_pace__DOT__mplier_q, m.mplier_q.read()},
        {"macc_q", r.dda_pace__DOT__macc_q, m.macc_q.read()},
        {"mcnt_q", r.dda_pace__DOT__mcnt_q, m.mcnt_q.read()},
        {"eff_q", r.dda_pace__DOT__eff_q, m.eff_q.read()},
        {"u_norm.cyc_q", r.dda_pace__DOT__u_norm__DOT__cyc_q, n.cyc_q.read()},
        {"u_norm.r_q", r.dda_pace__DOT__u_norm__DOT__r_q, n.r_q.read()},
        {"u_norm.c_q", r.dda_pace__DOT__u_norm__DOT__c_q, n.c_q.read()},
        {"u_norm.q_q", r.dda_pace__DOT__u_norm__DOT__q_q, n.q_q.read()},
        {"u_norm.sq_q", r.dda_pace__DOT__u_norm__DOT__sq_q, n.sq_q.read()},
        {"u_norm.mc_q", r.dda_pace__DOT__u_norm__DOT__mc_q, n.mc_q.read()},
        {"u_norm.a_q", r.dda_pace__DOT__u_norm__DOT__a_q, n.a_q.read()},
        {"u_norm.s_q", r.dda_pace__DOT__u_norm__DOT__s_q, n.s_q.read()},
        {"u_norm.rem_q", r.dda_pace__DOT__u_norm__DOT__rem_q, n.rem_q.read()},
        {"u_norm.root_q", r.dda_pace__DOT__u_norm__DOT__root_q, n.root_q.read()},
        {"u_norm.d_q", r.dda_pace__DOT__u_norm__DOT__d_q, n.d_q.read()},
    };
    for (const auto& g : regs) {
      if (g.rtl != g.sc)
        FAIL("after clock " << clock - 1 << ": " << g.name << " rtl " << g.rtl << ", SystemC " << g.sc);
    }
    if (std::uint64_t(rtl->speed_o) != speed.read()) FAIL("after clock " << clock - 1 << ": speed_o");
  }
};

}  // namespace

TEST_CASE("pace unit: SystemC model and RTL equal in every register on every edge", "[pacer][rtl][systemc]") {
  Bench b;
  ArcSpec s;
  s.a = 500;
  s.b = 200;
  s.angle = 20000000;
  s.preload = Preload::Half;
  s.from_theta = 30000000;
  s.to_theta = 250000000;
  const Plan plan = plan_arc(s);
  PaceHooks h;
  h.clock_by_clock = true;
  h.each = [](std::uint64_t clock, PaceSettings& set) {
    set.hold = clock >= 30000 && clock < 45000;
    set.override_ = clock < 60000    ? kOverrideOne
                    : clock < 80000  ? 0
                    : clock < 100000 ? kOverrideOne / 2
                                     : 2 * kOverrideOne;
  };
  h.edge = [&](const Pacer&, const Pacer::In& in) {
    b.inputs(in);
    b.edge();
  };
  h.watch = [&](std::uint64_t, const Pacer&, double) { b.compare(); };
  const PaceResult r = pace_plan(plan, PaceOptions{1.5e4, 1e7, 300, 16e6}, h);
  CHECK(r.end == plan.to);
  CHECK(b.clock > 100000);
}
