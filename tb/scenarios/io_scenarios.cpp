// SPDX-License-Identifier: Apache-2.0
#include "tb/scenarios/io_scenarios.hpp"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "host/driver/homing.hpp"
#include "host/planner/planner.hpp"
#include "model/datapath/errors.hpp"
#include "model/machine/machine_sim.hpp"
#include "tb/scenarios/scenario_kit.hpp"

namespace dda::motion {

namespace {

using namespace scenario;

// Fails on any pulse that starts toward a limit the block had filtered as active before
// that edge (the hard stop drops such steps: none may reach the pins).
class LimitWatch : public BusTap {
 public:
  explicit LimitWatch(BusTarget& t) : BusTap(t) {}
  void tick(const BusIn& bus) override {
    const auto lvl = [&](const char* inst) {
      return t_.model().regs()[breg(std::string("u_io.") + inst + ".lvl_q")] != 0;
    };
    const bool xn = lvl("u_lxn"), xp = lvl("u_lxp");
    t_.tick(bus);
    const int r = t_.model().rise_x();
    if ((r < 0 && xn) || (r > 0 && xp)) ++violations;
  }
  int violations = 0;
};

// An E-stop in the middle of a piece: the block stops filter + 3 edges after the pin
// falls (two to synchronize, the filter's, one to act), no pulse starts after that
// edge, LATCH_* hold the positions it stopped at; the block stays stopped (commits
// refused) until the pin is released and CTRL.clear.
void estop_mid_piece(BusTarget& block, const Expect& ex) {
  fresh(block);
  MachineSim t(block, Point{}, MachineSwitches{});
  const auto master = make_master(block.bus(), t, 7, false, 0);
  BusMaster& m = *master;
  MotionDriver d(m, 7);
  constexpr std::uint32_t kFilter = 4;
  d.set_inputs(0, kFilter, 1, 0);
  queue_unpaced(d, Point{3000, 1100, 0}, 4);
  run_until(
      m, [&] { return reg32(t, "pos_x_q") >= 400; }, 100000, "X past 400");
  bool low = true;
  t.force = [&](MachinePins& p) { p.estop_n = !low; };
  int edges = 0;
  while (reg32(t, "aborted_q") == 0) {
    m.idle(1);
    ++edges;
    if (edges >= 100) throw GuardError("machine scenario: the E-stop did not stop the block in 100 edges");
  }
  ex.eq(edges, int(kFilter) + 3, "edges == int(kFilter) + 3");
  const Point stopped{reg32(t, "pos_x_q"), reg32(t, "pos_y_q"), 0};
  ex(stopped.x > 400, "stopped.x > 400");
  ex.eq(status(d, "err_estop"), 1, "status(d, \"err_estop\") == 1");
  ex.eq(status(d, "err"), 1, "status(d, \"err\") == 1");
  ex.eq(d.read("TRIP"), in_bit("estop"), "d.read(\"TRIP\") == in_bit(\"estop\")");
  ex.eq(d.positions("LATCH"), stopped, "d.positions(\"LATCH\") == stopped");
  m.idle(200);
  ex.eq(d.position(), stopped, "d.position() == stopped");
  ex.eq(t.physical(), stopped, "t.physical() == stopped");
  // Released but not cleared: still stopped, a commit is refused.
  low = false;
  m.idle(20);
  ex.eq((d.read("INPUTS") & in_bit("estop")), 0, "(d.read(\"INPUTS\") & in_bit(\"estop\")) == 0");
  queue_unpaced(d, Point{50, 0, 0}, 1);
  m.idle(50);
  ex.eq(status(d, "level"), 0, "status(d, \"level\") == 0");
  ex.eq(d.position(), stopped, "d.position() == stopped");
  d.clear();
  ex.eq(status(d, "err_estop"), 0, "status(d, \"err_estop\") == 0");
  queue_unpaced(d, Point{50, 0, 0}, 1);
  d.drain();
  ex.eq(d.position().x, stopped.x + 50, "d.position().x == stopped.x + 50");
  // LATCH_* keep the trip's positions through the clear and the moves after it.
  ex.eq(d.positions("LATCH"), stopped, "d.positions(\"LATCH\") == stopped after the clear");
}

// A limit hit during a move, in both stop modes. Hard: no pulse ever starts toward the
// active limit (LimitWatch), the machine stops on the switch's filtered edge; a move away
// from it runs, a move toward it stops before its first pulse. At the deceleration
// (IN_MODE.limit_decel): a soft stop ramps down at ACCEL, over the switch by at most
// the braking distance.
void limit_hard(BusTarget& block, const Expect& ex) {
  fresh(block);
  MachineSwitches sw;
  sw.limit_pos[0] = 800;
  sw.active_low = in_bit("limit_x_pos");  // wired active low, IN_POLARITY says so
  LimitWatch w(block);
  MachineSim t(w, Point{}, sw);
  const auto master = make_master(block.bus(), t, 11, true, 10);
  BusMaster& m = *master;
  MotionDriver d(m, 11);
  d.set_inputs(in_bit("limit_x_pos"), 3, 1, 0);
  queue_unpaced(d, Point{2000, 500, 0}, 8);
  d.wait_rest();
  ex.eq(status(d, "err_limit"), 1, "status(d, \"err_limit\") == 1");
  ex.eq(d.read("TRIP"), in_bit("limit_x_pos"), "d.read(\"TRIP\") == in_bit(\"limit_x_pos\")");
  const Point stopped = d.position();
  ex(stopped.x >= 800, "stopped.x >= 800");
  ex(stopped.x <= 802, "stopped.x <= 802");  // the pulses of the filter's delay, at one step per 8 clocks at most
  ex.eq(d.positions("LATCH"), stopped, "d.positions(\"LATCH\") == stopped");
  ex.eq(t.physical(), stopped, "t.physical() == stopped");
  // Toward the active limit: stopped before a pulse.
  d.clear();
  queue_unpaced(d, Point{100, 0, 0}, 1);
  d.wait_rest();
  ex.eq(d.position(), stopped, "d.position() == stopped");
  ex.eq(status(d, "err_limit"), 1, "status(d, \"err_limit\") == 1");
  // Away from it: runs to its end.
  d.clear();
  queue_unpaced(d, Point{-300, -20, 0}, 1);
  d.drain();
  ex.eq(d.position(), Point{stopped.x - 300, stopped.y - 20, 0},
        "d.position() == Point{stopped.x - 300, stopped.y - 20, 0}");
  ex.eq(status(d, "err_limit"), 0, "status(d, \"err_limit\") == 0");
  ex.eq(w.violations, 0, "w.violations == 0");
}

void limit_decel(BusTarget& block, const Expect& ex) {
  fresh(block);
  MachineSwitches sw;
  sw.limit_neg[1] = -200;
  MachineSim t(block, Point{}, sw);
  const auto master = make_master(block.bus(), t, 13, false, 0);
  BusMaster& m = *master;
  MotionDriver d(m, 13);
  d.set_pacing(kAccel, kVmin);
  d.set_inputs(0, 2, 1, field_bit("IN_MODE", "limit_decel"));
  queue_move(d, Point{300, -4000, 0}, kFast);
  run_until(
      m, [&] { return reg32(t, "stopping_q") != 0; }, 400000, "a soft stop");
  d.wait_rest();
  ex.eq(status(d, "err_limit"), 1, "status(d, \"err_limit\") == 1");
  ex.eq(d.read("TRIP"), in_bit("limit_y_neg"), "d.read(\"TRIP\") == in_bit(\"limit_y_neg\")");
  const Point p = d.position();
  // Past the switch by no more than the braking distance from the cruise speed (32
  // steps) and the filter's delay.
  ex(p.y < -200 - 4, "p.y < -200 - 4");
  ex(p.y > -200 - 34, "p.y > -200 - 34");
  ex(d.positions("LATCH").y <= -200, "d.positions(\"LATCH\").y <= -200");
  ex.eq(t.physical(), p, "t.physical() == p");
}

// Homing each axis on a machine whose switches sit at positions the driver does not
// know: after the cycle, the axis' position reads home_position exactly where the
// switch turns active on the slow approach.
void home_each_axis(BusTarget& block, const Expect& outer) {
  fresh(block);
  MachineSwitches sw;
  sw.home = {-900, 700, -400};
  sw.home_positive = {false, true, false};
  sw.active_low = in_bit("home_y");
  const Point start{-840, 640, -340};
  MachineSim t(block, start, sw);
  const auto master = make_master(block.bus(), t, 17, false, 0);
  BusMaster& m = *master;
  MotionDriver d(m, 17);
  d.read_build();
  if (d.pacer()) d.set_pacing(kAccel << 2, kVmin);  // braking from the search speed: 8 steps (no pacer: none)
  d.set_inputs(in_bit("home_y"), 3, 1, 0);
  d.preset(Point{5000, -5000, 12});  // the block's count: anything before homing
  const std::array<std::int64_t, 3> home_at{-900, 700, -400};
  for (std::size_t j = 0; j < 3; ++j) {
    const char axis = kAxes[j];
    const Expect ex([&](bool ok, const std::string& what) { outer(ok, std::string("axis ") + axis + ": " + what); });
    HomingParams hp;
    hp.axis = axis;
    hp.positive = sw.home_positive[j];
    hp.search_steps = 400;
    hp.backoff_steps = 8;
    hp.search_speed = kFast;
    hp.latch_speed = kSlow;
    hp.home_position = std::int32_t(10 * (j + 1));
    const HomingResult r = home_axis(d, hp);
    // The block's position minus the machine's: what the switch's edge reads, less its place.
    const Point pos = d.position(), phys = t.physical();
    const std::array<std::int64_t, 3> pv{pos.x, pos.y, pos.z}, ph{phys.x, phys.y, phys.z};
    ex.eq(pv[j] - ph[j], hp.home_position - home_at[j], "pv[j] - ph[j] == hp.home_position - home_at[j]");
    // The fast search found the same edge, within a step.
    ex(std::abs(r.second_latch - r.first_latch) <= 1, "std::abs(r.second_latch - r.first_latch) <= 1");
    ex.eq(d.read("IN_MODE"), 0, "d.read(\"IN_MODE\") == 0");
    ex.eq(d.read("TRIP"), 0, "d.read(\"TRIP\") == 0");
  }
}

// A probing move (G38.2): down in Z toward a surface; the block stops on the probe and
// PROBE_* holds the position at contact (exact at the slow speed: the filter's delay
// is shorter than a step); a move that never touches is an error. Before it, the probe
// touched and released while disarmed (a plain move through the surface and back, with
// IN_MODE.probe_stop on): no latch, no interrupt, no stop.
void probing(BusTarget& block, const Expect& ex) {
  fresh(block);
  MachineSwitches sw;
  sw.probe_z = -20;
  MachineSim t(block, Point{}, sw);
  const auto master = make_master(block.bus(), t, 19, true, 5);
  BusMaster& m = *master;
  MotionDriver d(m, 19);
  d.set_pacing(kAccel, kVmin);
  d.set_inputs(0, 2, 3, 0);
  d.write("IRQ_ENABLE", field_bit("IRQ_ENABLE", "probe"));
  d.write("IN_MODE", field_bit("IN_MODE", "probe_stop"));
  queue_move(d, Point{0, 0, -25}, kFast);
  d.drain();
  ex.eq(d.position(), Point{0, 0, -25}, "disarmed: the move through the surface runs to its end");
  ex.eq((d.read("INPUTS") >> kProbeBit) & 1u, 1, "disarmed: the probe is seen touching");
  queue_move(d, Point{0, 0, 25}, kFast);
  d.drain();
  ex.eq(d.position(), Point{}, "disarmed: back up");
  ex.eq(status(d, "probed"), 0, "disarmed: STATUS.probed stays 0");
  ex.eq(get_field("IRQ_STATUS", "probe", d.read("IRQ_STATUS")), 0, "disarmed: no IRQ_STATUS.probe");
  ex(!t.outputs().irq, "disarmed: no interrupt");
  ex.eq(d.read("PROBE_Z"), 0, "disarmed: PROBE_Z latched nothing");
  d.write("IN_MODE", 0);
  const Point hit = probe_move(d, Point{2, 0, -100}, kSlow);
  ex.eq(hit.z, -20, "hit.z == -20");
  ex(t.outputs().irq, "t.outputs().irq");
  ex.eq(get_field("IRQ_STATUS", "probe", d.read("IRQ_STATUS")), 1,
        "get_field(\"IRQ_STATUS\", \"probe\", d.read(\"IRQ_STATUS\")) == 1");
  ex.eq(status(d, "probed"), 1, "status(d, \"probed\") == 1");
  ex.eq(status(d, "probe_armed"), 0, "status(d, \"probe_armed\") == 0");
  const Point rest = d.position();
  ex(rest.z <= -20, "rest.z <= -20");
  ex(rest.z > -20 - 3, "rest.z > -20 - 3");  // braking from 1/512 step per clock: half a step
  ex.eq(t.physical(), rest, "t.physical() == rest");
  // Up and away from the surface, then a move that never reaches it.
  queue_move(d, Point{0, 0, 60}, kFast);
  d.drain();
  bool refused = false;
  try {
    probe_move(d, Point{1, 0, -30}, kFast);
  } catch (const GuardError& e) {
    refused = std::string(e.what()).find("no contact") != std::string::npos;
  }
  ex(refused, "a probing move without contact is refused (no contact)");
}

// One clock's registers the snapshot latches, by the cycle counter's value in that clock.
struct SnapRec {
  std::int32_t x, y;
  std::uint32_t level, done;
};
using SnapHistory = std::map<std::uint32_t, SnapRec>;
void record_snapshots(MachineSim& t, SnapHistory& hist) {
  t.force = [&t, &hist](MachinePins&) {
    hist[std::uint32_t(t.model().regs()[breg("u_io.cycle_q")])] =
        SnapRec{reg32(t, "pos_x_q"), reg32(t, "pos_y_q"), std::uint32_t(reg32(t, "level_q")),
                std::uint32_t(reg32(t, "done_count_q"))};
  };
}
// The snapshot's registers are the clock's it names; returns that clock's record and the
// next clock's (the edge the snapshot was written on), or nothing.
std::optional<std::pair<SnapRec, SnapRec>> check_snapshot(const MotionDriver::Snapshot& s, const SnapHistory& hist,
                                                          const Expect& ex) {
  const auto at = hist.find(s.cycle), next = hist.find(s.cycle + 1);
  ex(at != hist.end() && next != hist.end(), "SNAP_CYCLE is a cycle of the run");
  if (at == hist.end() || next == hist.end()) return std::nullopt;
  const SnapRec& r = at->second;
  ex.eq(s.pos.x, r.x, "s.pos.x == r.x");
  ex.eq(s.pos.y, r.y, "s.pos.y == r.y");
  ex.eq(s.level, r.level, "s.level == r.level");
  ex.eq(s.done, r.done, "s.done == r.done");
  return std::make_pair(r, next->second);
}

// The snapshot on the edges where the queue level changes, atomic there: written in one
// CTRL write with a commit (SNAP_LEVEL the level before it), with an abort, and a clock
// at a time across a take (each run from reset, the same but for when the snapshot is
// written: the clocks before the take, the take's own edge, the clocks after).
void snapshot_edges(BusTarget& block, const Expect& ex) {
  const auto run = [&](SnapHistory& hist, std::int64_t wait, const std::function<void(MotionDriver&)>& at_end) {
    fresh(block);
    MachineSim t(block, Point{}, MachineSwitches{});
    record_snapshots(t, hist);
    const auto master = make_master(block.bus(), t, 31, false, 0);
    BusMaster& m = *master;
    MotionDriver d(m, 31);
    queue_unpaced(d, Point{400, 300, 0}, 3);
    queue_unpaced(d, Point{-20, 10, 0}, 3);
    const std::uint32_t queued = std::uint32_t(reg32(t, "u_io.cycle_q"));
    if (wait > 0) m.idle(int(wait));
    at_end(d);
    return queued;
  };
  // With a commit: the level goes up on the snapshot's own edge.
  {
    SnapHistory hist;
    run(hist, 0, [&](MotionDriver& d) {
      const Plan p = plan_line(Point{}, Point{5, 5, 0}, Preload::Half);
      d.queue(p.pieces[0].cmd, 0, 0, {}, field_bit("CTRL", "snapshot"));
      const auto r = check_snapshot(d.snapshot_registers(), hist, ex);
      ex(r && r->second.level == r->first.level + 1, "the commit's edge is the snapshot's");
      d.drain();
    });
  }
  // With an abort: the level drops to 0 on the snapshot's own edge.
  {
    SnapHistory hist;
    run(hist, 20, [&](MotionDriver& d) {
      d.write("CTRL", field_bit("CTRL", "abort") | field_bit("CTRL", "snapshot"));
      const auto r = check_snapshot(d.snapshot_registers(), hist, ex);
      ex(r && r->first.level > 0 && r->second.level == 0, "the abort's edge is the snapshot's");
    });
  }
  // Across the take of the second line: find its edge, and where a snapshot right after
  // the queueing lands, then land one on each clock from 3 before to 3 after.
  SnapHistory cal;
  std::uint32_t landed = 0;
  const std::uint32_t queued = run(cal, 0, [&](MotionDriver& d) {
    landed = d.snapshot().cycle;
    d.drain();
  });
  std::optional<std::uint32_t> take;
  for (auto it = cal.find(queued); it != cal.end() && std::next(it) != cal.end(); ++it) {
    if (std::next(it)->second.level + 1 == it->second.level) {
      take = it->first;
      break;
    }
  }
  ex(take.has_value() && *take > landed + 3, "the second line's take comes after the queueing");
  if (!take || *take <= landed + 3) return;
  int on_take = 0;
  for (std::uint32_t c = *take - 3; c <= *take + 3; ++c) {
    SnapHistory hist;
    run(hist, std::int64_t(c) - std::int64_t(landed), [&](MotionDriver& d) {
      const MotionDriver::Snapshot s = d.snapshot();
      ex.eq(s.cycle, c, "the snapshot lands on the clock asked");
      const auto r = check_snapshot(s, hist, ex);
      on_take += r && r->second.level + 1 == r->first.level;
    });
  }
  ex.eq(on_take, 1, "one snapshot on the take's edge");
}

// The snapshot while two axes run: each SNAP_* set equals the positions, level and count
// the block held in one clock (recorded here, before every edge, from the registers),
// where reading POS_X then POS_Y gives two clocks' values.
void snapshot_moving(BusTarget& block, const Expect& ex) {
  fresh(block);
  struct Rec {
    std::int32_t x, y;
    std::uint32_t level, done;
  };
  std::map<std::uint32_t, Rec> hist;  // by the cycle counter's value in that clock
  MachineSim t(block, Point{}, MachineSwitches{});
  t.force = [&](MachinePins&) {
    hist[std::uint32_t(t.model().regs()[breg("u_io.cycle_q")])] =
        Rec{reg32(t, "pos_x_q"), reg32(t, "pos_y_q"), std::uint32_t(reg32(t, "level_q")),
            std::uint32_t(reg32(t, "done_count_q"))};
  };
  const auto master = make_master(block.bus(), t, 23, false, 30);
  BusMaster& m = *master;
  MotionDriver d(m, 23);
  for (int k = 0; k < 3; ++k) queue_unpaced(d, Point{900, 700, 0}, 3);
  int moving = 0;
  for (int k = 0; k < 12; ++k) {
    m.idle(250);
    const MotionDriver::Snapshot s = d.snapshot();
    const auto at = hist.find(s.cycle);
    ex(at != hist.end(), "SNAP_CYCLE is a cycle of the run");
    if (at == hist.end()) continue;
    const Rec& r = at->second;
    ex.eq(s.pos.x, r.x, "s.pos.x == r.x");
    ex.eq(s.pos.y, r.y, "s.pos.y == r.y");
    ex.eq(s.level, r.level, "s.level == r.level");
    ex.eq(s.done, r.done, "s.done == r.done");
    const Point a = d.position();
    moving += a.x != s.pos.x && a.y != s.pos.y;
  }
  ex(moving >= 6, "moving >= 6");  // both axes moved between the snapshot and the reads
  snapshot_edges(block, ex);
}

// Pulses shorter than the filter are ignored on every input; one as long passes.
void glitches(BusTarget& block, const Expect& outer) {
  fresh(block);
  MachineSim t(block, Point{}, MachineSwitches{});
  const auto master = make_master(block.bus(), t, 29, false, 0);
  BusMaster& m = *master;
  MotionDriver d(m, 29);
  constexpr int kSw = 6, kProbe = 3;
  d.set_inputs(0, kSw, kProbe,
               field_bit("IN_MODE", "home_x") | field_bit("IN_MODE", "home_y") | field_bit("IN_MODE", "home_z"));
  d.arm_probe();
  std::uint32_t pulse = 0;  // the inputs pulsed (kInputs' order)
  int left = 0;
  t.force = [&](MachinePins& p) {
    if (left <= 0) return;
    --left;
    p = MachinePins::from_bits(p.bits() ^ pulse);  // (estop_ni pulses low)
  };
  queue_unpaced(d, Point{-4000, 3000, 0}, 4);  // toward x-, y+: the limits it would hit
  for (const auto& in : kInputs) {
    const Expect ex(
        [&](bool ok, const std::string& what) { outer(ok, "input " + std::string(in.name) + ": " + what); });
    const int filter = in.bit == kProbeBit ? kProbe : kSw;
    for (int len = 1; len < filter; ++len) {
      pulse = 1u << in.bit;
      left = len;
      m.idle(len + filter + 4);
    }
    ex.eq(d.read("TRIP"), 0, "d.read(\"TRIP\") == 0");
    ex.eq(status(d, "probed"), 0, "status(d, \"probed\") == 0");
    ex.eq(status(d, "err"), 0, "status(d, \"err\") == 0");
    ex.eq(status(d, "busy"), 1, "status(d, \"busy\") == 1");
  }
  // As long as the filter: the probe latches, an E-stop stops.
  pulse = in_bit("probe");
  left = kProbe;
  m.idle(kProbe + 6);
  outer.eq(status(d, "probed"), 1, "status(d, \"probed\") == 1");
  pulse = in_bit("estop");
  left = kSw;
  m.idle(kSw + 6);
  outer.eq(d.read("TRIP"), in_bit("estop"), "d.read(\"TRIP\") == in_bit(\"estop\")");
  outer.eq(status(d, "busy"), 0, "status(d, \"busy\") == 0");
}
}  // namespace

const std::array<IoScenario, 10> kIoScenarios{{
    {"estop", "an E-stop in the middle of a piece", estop_mid_piece},
    {"limit-hard", "a limit hit during a move, stopped as a hard stop", limit_hard},
    {"limit-decel", "a limit hit during a paced move, stopped at ACCEL", limit_decel, kNeedsPacer},
    {"homing", "a homing cycle on each axis", home_each_axis, kNeedsZ},
    {"probing", "a touch while disarmed, a probing move that stops on the probe, and one that never touches", probing,
     kNeedsPacer | kNeedsZ},
    {"snapshot", "snapshots while two axes run", snapshot_moving},
    {"glitches", "pulses shorter than the filter on every input", glitches},
    {"overflow", "the queue filled to its depth and one entry more", queue_overflow, kNeedsFastBus},
    {"limits", "each of the six limits hit on a move toward it", each_limit, kNeedsZ},
    {"ranges", "every register, position, command field, speed, filter and timing at its full width", field_ranges,
     kNeedsPacer | kNeedsZ | kNeedsFastBus},
}};

const IoScenario* find_io_scenario(std::string_view name) {
  for (const auto& s : kIoScenarios) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

std::string Expect::text(const Point& p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

}  // namespace dda::motion
