// SPDX-License-Identifier: Apache-2.0
// The block's scenarios at the ends of its ranges (io_scenarios.hpp): a queue filled past
// its depth, each of the six limits, and every field at its full width: registers,
// positions, commands whose capacities and integrands reach the core's contract
// (0 <= jv <= cap < 2^(AccWidth-1)), the pacer at the top of its speeds and
// accelerations, a stalled command, the input filters at their longest and the step/dir
// timings at theirs. The engines that run them are compared with the reference model on
// every edge; what the block must do besides is an Expect here.
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "model/machine/machine_sim.hpp"
#include "model/motion/pacer.hpp"
#include "tb/scenarios/io_scenarios.hpp"
#include "tb/scenarios/scenario_kit.hpp"

namespace dda::motion {

using namespace scenario;

namespace {

void ctrl(MotionDriver& d, std::string_view bit) { d.write("CTRL", field_bit("CTRL", bit)); }

// Every field of a register: the bits a write keeps.
std::uint32_t writable(std::string_view reg) {
  std::uint32_t mask = 0;
  for (const Field& f : map().fields) {
    if (f.reg == reg) mask |= std::uint32_t((std::uint64_t{1} << f.width) - 1) << f.lsb;
  }
  return mask;
}

// The entry words of `c` written and committed by hand (MotionDriver::queue waits for
// room: these go into a full queue).
void commit_words(BusMaster& m, const Command& c) {
  const std::vector<std::uint32_t> w = entry_words(c);
  for (std::size_t j = 0; j < w.size(); ++j) m.write(reg_offset("ENTRY") + 4 * std::uint32_t(j), w[j]);
  m.write(reg_offset("CTRL"), field_bit("CTRL", "commit"));
}

}  // namespace

// A slow line holds the core while single-step entries fill the queue behind it to its
// depth (SNAP_LEVEL one short of it and at it, STATUS.full); one more entry is refused (err_overflow, the level
// kept); after CTRL.clear everything queued runs and nothing refused does.
void queue_overflow(BusTarget& block, const Expect& ex) {
  fresh(block);
  MachineSim t(block, Point{}, MachineSwitches{});
  const auto master = make_master(block.bus(), t, 37, true, 0);
  BusMaster& m = *master;
  MotionDriver d(m, 37, false);
  const std::uint32_t depth = 1u << get_field("CONFIG", "depth_log2", d.read("CONFIG"));
  d.write("IRQ_LEVEL", depth - 1);
  d.write("IRQ_ENABLE", field_bit("IRQ_ENABLE", "low"));
  queue_unpaced(d, Point{6000, 1500, 0}, 8);
  const Command one = plan_line(Point{}, Point{1, 0, 0}, Preload::Half).pieces.front().cmd;
  for (std::uint32_t k = 0; k + 1 < depth; ++k) commit_words(m, one);
  ex.eq(d.snapshot().level, depth - 1, "d.snapshot().level == depth - 1");
  ex.eq(status(d, "full"), 0, "status(d, \"full\") == 0");
  commit_words(m, one);
  ex.eq(status(d, "full"), 1, "status(d, \"full\") == 1");
  ex.eq(status(d, "level"), depth, "status(d, \"level\") == depth");
  ex.eq(d.snapshot().level, depth, "d.snapshot().level == depth");
  ex.eq(status(d, "err"), 0, "status(d, \"err\") == 0");
  commit_words(m, one);
  ex.eq(status(d, "err_overflow"), 1, "status(d, \"err_overflow\") == 1");
  ex.eq(status(d, "level"), depth, "status(d, \"level\") == depth");
  d.clear();
  ex.eq(status(d, "err_overflow"), 0, "status(d, \"err_overflow\") == 0");
  d.drain();
  ex.eq(d.position(), Point{6000 + std::int64_t(depth), 1500, 0}, "d.position() == Point{6000 + depth, 1500, 0}");
  ex.eq(get_field("IRQ_STATUS", "low", d.read("IRQ_STATUS")), 1,
        "get_field(\"IRQ_STATUS\", \"low\", d.read(\"IRQ_STATUS\")) == 1");
  ex(t.outputs().irq, "t.outputs().irq");
  // A commit before every word of an entry is written, then an entry word on two byte
  // lanes: each refused with its cause and the sticky error.
  m.write(reg_offset("ENTRY"), 1);
  m.write(reg_offset("CTRL"), field_bit("CTRL", "commit"));
  ex.eq(status(d, "err_partial"), 1, "status(d, \"err_partial\") == 1");
  ex.eq(status(d, "err"), 1, "status(d, \"err\") == 1");
  d.clear();
  m.write(reg_offset("ENTRY"), 1, 0x3);
  ex.eq(status(d, "err_lanes"), 1, "status(d, \"err_lanes\") == 1");
  ex.eq(status(d, "err"), 1, "status(d, \"err\") == 1");
  ex.eq(status(d, "level"), 0, "status(d, \"level\") == 0");
  d.clear();
}

// Each of the six limits (hard stop): a move toward the switch stops on it with its bit
// in TRIP (err_limit, LATCH_* at the stop); after CTRL.clear the move away runs to its end.
void each_limit(BusTarget& block, const Expect& outer) {
  fresh(block);
  MachineSim t(block, Point{}, MachineSwitches{});
  const auto master = make_master(block.bus(), t, 41, false, 3);
  BusMaster& m = *master;
  MotionDriver d(m, 41);
  d.set_inputs(0, 2, 1, 0);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    for (const int sign : {-1, 1}) {
      const std::string name = std::string("limit_") + kAxes[axis] + (sign < 0 ? "_neg" : "_pos");
      const Expect ex([&](bool ok, const std::string& what) { outer(ok, name + ": " + what); });
      const Point here = t.physical();
      const std::int64_t at[3] = {here.x, here.y, here.z};
      auto& sw = sign < 0 ? t.switches().limit_neg : t.switches().limit_pos;
      sw[axis] = at[axis] + sign * 30;
      Point toward, away;
      (axis == 0 ? toward.x : axis == 1 ? toward.y : toward.z) = sign * 100;
      (axis == 0 ? away.x : axis == 1 ? away.y : away.z) = -sign * 100;
      toward = toward + Point{7, -5, 3};  // another axis moves too
      queue_unpaced(d, toward, 4);
      d.wait_rest();
      ex.eq(d.read("TRIP"), in_bit(name), "d.read(\"TRIP\") == in_bit(name)");
      ex.eq(status(d, "err_limit"), 1, "status(d, \"err_limit\") == 1");
      const Point stopped = d.position();
      ex.eq(d.positions("LATCH"), stopped, "d.positions(\"LATCH\") == stopped");
      ex.eq(t.physical(), stopped, "t.physical() == stopped");
      d.clear();
      queue_unpaced(d, away, 2);
      d.drain();
      ex.eq(d.position(), stopped + away, "d.position() == stopped + away");
      sw[axis].reset();
      m.idle(8);
      d.clear();
      ex.eq(status(d, "err"), 0, "status(d, \"err\") == 0");
    }
  }
}

namespace {

// Every read/write register but the positions at all ones, at random values and at 0:
// each reads back what it keeps (OVERRIDE at most 200%); the watchdog written 0 last (off).
void register_ranges(MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  for (const Register& r : kRegisters) {
    if (r.access != Access::RW || r.name.substr(0, 4) == "POS_") continue;
    const std::string name(r.name);
    const std::uint32_t mask = writable(name);
    for (const std::uint32_t v : {~0u, std::uint32_t(rng()), std::uint32_t(rng()), 0u}) {
      d.write(name, v);
      const std::uint32_t kept = name == "OVERRIDE" ? std::min(v & mask, 2 * kOverrideOne) : v & mask;
      ex.eq(d.read(name), kept, name + " reads back what a write keeps");
    }
  }
  d.write("OVERRIDE", kOverrideOne);
  d.clear();
}

// The positions preset to a value and to its complement (every bit both ways): POS_*,
// SNAP_* and PROBE_* (the probe's edge while armed) read them.
void position_ranges(MachineSim& t, BusMaster& m, MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  const auto s32 = [](std::uint32_t v) { return std::int64_t(std::int32_t(v)); };
  const std::uint32_t vx = std::uint32_t(rng()), vy = std::uint32_t(rng()), vz = std::uint32_t(rng());
  d.set_inputs(0, 2, 2, 0);
  for (const Point p : {Point{s32(vx), s32(vy), s32(vz)}, Point{s32(~vx), s32(~vy), s32(~vz)}}) {
    d.preset(p);
    ex.eq(d.position(), p, "d.position() == p");
    ex.eq(d.snapshot().pos, p, "d.snapshot().pos == p");
    d.arm_probe();
    t.force = [](MachinePins& pins) { pins.probe = true; };
    m.idle(8);
    t.force = nullptr;
    m.idle(8);
    ex.eq(status(d, "probed"), 1, "status(d, \"probed\") == 1");
    ex.eq(d.positions("PROBE"), p, "d.positions(\"PROBE\") == p");
  }
  d.preset(Point{});
}

// Commands that can never go on (X or Z still to step, its integrand 0 and never corrected):
// the core stops each (STATUS.err_stall, ERR_COUNT counts them) and the block takes the
// next; an empty command (no step on any axis) ends at once and is counted as done.
void stalled_commands(MotionDriver& d, const Expect& ex) {
  Command c;
  c.cap = 16;
  c.cnt_x = 3;
  c.cap_z = 16;  // the third axis idle (no step to make) with an integrand: it cannot go on
  c.jv_z = 5;
  Command z;  // the third axis likewise: a step to make, its integrand 0
  z.cap_z = 16;
  z.cnt_z = 2;
  const std::uint32_t done = d.read("DONE_COUNT");
  for (int k = 0; k < 3; ++k) d.queue(c);
  d.queue(z);
  d.queue(Command{});
  queue_unpaced(d, Point{5, 2, 0}, 1);
  d.drain();
  ex.eq(status(d, "err_stall"), 1, "status(d, \"err_stall\") == 1");
  ex.eq(d.read("ERR_COUNT"), 4, "d.read(\"ERR_COUNT\") == 4");
  ex.eq(d.read("DONE_COUNT"), done + 2, "d.read(\"DONE_COUNT\") == done + 2");
  ex.eq(d.position(), Point{5, 2, 0}, "d.position() == Point{5, 2, 0}");
  d.clear();
  d.preset(Point{});
}

// Paced pieces where one axis ends its steps first, its integrand not 0: from then on the
// norm unit leaves that axis out (the pacer's d is the others' alone), each piece ends on
// its point.
void uneven_axes(MotionDriver& d, const Expect& ex) {
  d.set_pacing(kAccel, kVmin);
  Point want = d.position();
  for (int axis = 0; axis < 3; ++axis) {
    Command c;
    c.cap = c.cap_z = 1024;
    c.jv_x = c.jv_y = c.jv_z = 1024;
    c.cnt_x = c.cnt_y = c.cnt_z = 40;
    (axis == 0 ? c.jv_x : axis == 1 ? c.jv_y : c.jv_z) = 512;   // a step every other iteration
    (axis == 0 ? c.cnt_x : axis == 1 ? c.cnt_y : c.cnt_z) = 8;  // done after 16 of 40
    d.queue(c, 0, 0, pace_entries({c}, kFast, kVmin, kAccel).front());
    want = want + Point{c.cnt_x, c.cnt_y, c.cnt_z};
  }
  d.drain();
  ex.eq(d.position(), want, "d.position() == want");
  d.preset(Point{});
}

// DONE_COUNT and SNAP_DONE through 2^9 - 1 to 2^9 (every bit below both ways): single
// steps, each counted, snapshots at both counts.
void done_counts(MotionDriver& d, const Expect& ex) {
  const Command one = plan_line(Point{}, Point{1, 0, 0}, Preload::Half).pieces.front().cmd;
  const std::uint32_t top = 1u << 9;
  for (std::uint32_t n = d.read("DONE_COUNT"); n < top - 1; ++n) d.queue(one);
  d.drain();
  ex.eq(d.snapshot().done, top - 1, "d.snapshot().done == top - 1");
  d.queue(one);
  d.drain();
  ex.eq(d.snapshot().done, top, "d.snapshot().done == top");
  d.preset(Point{});
}

// A paced entry of `c` at a random top speed (1/64 to 1 step per clock) and minimum
// speed (1/256 step per clock and up, no faster), at a random acceleration.
PaceEntry fast_pacing(MotionDriver& d, const Command& c, std::mt19937_64& rng) {
  const std::uint32_t cruise = (1u << 26) + std::uint32_t(rng() % ((1ull << 32) - (1u << 26)));
  const std::uint32_t vmin = std::min(cruise, (1u << 24) + std::uint32_t(rng() % (1u << 28)));
  const std::uint32_t accel = std::uint32_t(rng());
  d.set_pacing(accel, vmin);
  return pace_entries({c}, cruise, vmin, accel).front();
}

// Arcs whose capacity 2^n a b reaches the top of the contract (the largest n below
// 2^(AccWidth-1), one less every other arc): each piece started unpaced or paced at the
// top of the pacer's ranges, run a few hundred clocks and aborted.
void wide_arcs(BusMaster& m, MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  for (int k = 0; k < 8; ++k) {
    ArcSpec s;
    s.a = 16384 + std::int64_t(rng() % 16385);
    s.b = 16384 + std::int64_t(rng() % 16385);
    int n = 0;
    while ((std::uint64_t(s.a * s.b) << (n + 1)) < (std::uint64_t{1} << (hw::kAccWidth - 1))) ++n;
    s.bits = n - k % 2;
    s.dir = k % 4 < 2 ? Direction::Ccw : Direction::Cw;
    // From each quadrant's start (either integrand at its top); every other arc from an
    // angle off the lattice, the rest of its point in the preloads.
    const std::int64_t deg = 1000000;
    s.preload = k % 3 == 0 && k % 2 == 0 ? Preload::Zero : Preload::Half;
    s.from_theta = 90 * deg * (k % 4) + (k % 2 ? std::int64_t(rng() % (89 * deg)) : 0);
    s.to_theta = *s.from_theta + 45 * deg;
    const Plan plan = plan_arc(s);
    const Command& c = plan.pieces.front().cmd;
    d.preset(plan.from);
    d.queue(c, 0, 0, k % 2 ? fast_pacing(d, c, rng) : PaceEntry{});
    m.idle(300 + int(rng() % 600));
    ctrl(d, "abort");
    ex.eq(status(d, "aborted"), 1, "status(d, \"aborted\") == 1");
    d.clear();
  }
  d.preset(Point{});
}

// Lines whose capacities, integrands and preloads are drawn over the contract's whole
// range (capacities 2^40 .. 2^(AccWidth-1) - 1, integrands of at least half the
// capacity: a step every other iteration at most), on the plane's integrators and the
// third axis, every other line with capacities just below the contract's top (a
// preload plus an integrand then reaches 2^(AccWidth-1) and past: the compare needs
// every bit of the sum), on each of the block's axes (the entry's axes), unpaced or
// paced: each ends its steps on its axes.
void wide_lines(MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  const std::uint64_t top = std::uint64_t{1} << (hw::kAccWidth - 1), low = std::uint64_t{1} << 40;
  const auto capacity = [&](int k) { return std::int64_t(k % 2 ? top - 1 - rng() % low : low + rng() % (top - low)); };
  const auto draw = [&](std::int64_t cap, std::int64_t& jv, std::int64_t& jr, std::int64_t& cnt) {
    jv = cap - std::int64_t(rng() % std::uint64_t(cap / 2));
    jr = std::int64_t(rng() % std::uint64_t(cap));
    cnt = 1 + std::int64_t(rng() % 12);
  };
  Point want = d.position();
  for (int k = 0; k < 12; ++k) {
    Command c;
    c.cap = capacity(k);
    c.cap_z = capacity(k);
    draw(c.cap, c.jv_x, c.jr_x, c.cnt_x);
    draw(c.cap, c.jv_y, c.jr_y, c.cnt_y);
    draw(c.cap_z, c.jv_z, c.jr_z, c.cnt_z);
    c.dir_x_neg = rng() % 2 == 0;
    c.dir_y_neg = rng() % 2 == 0;
    c.dir_z_neg = rng() % 2 == 0;
    const int rot = k % 3;
    d.queue(c, 0, rot, k % 2 ? fast_pacing(d, c, rng) : PaceEntry{});
    const Point moved{c.dir_x_neg ? -c.cnt_x : c.cnt_x, c.dir_y_neg ? -c.cnt_y : c.cnt_y,
                      c.dir_z_neg ? -c.cnt_z : c.cnt_z};
    want = want + to_run_axes(moved, rot);
  }
  d.drain();
  ex.eq(d.position(), want, "d.position() == want");
}

// A long 3-D line: its first two pieces (the longest a piece may be) paced at the top of
// the pacer's ranges, aborted after a few thousand clocks.
void long_line(BusMaster& m, MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  const Plan plan = plan_line(Point{}, Point{1 << 22, -(3 << 20), 5 << 19}, Preload::Half);
  const std::vector<Command> cmds{plan.pieces[0].cmd, plan.pieces[1].cmd};
  const std::uint32_t accel = std::uint32_t(rng()) | 1u << 31;
  d.set_pacing(accel, 1u << 26);
  const std::vector<PaceEntry> pace = pace_entries(cmds, 0xFFFFFFFFu, 1u << 26, accel);
  for (std::size_t k = 0; k < cmds.size(); ++k) d.queue(cmds[k], 0, plan.pieces[k].rot, pace[k]);
  m.idle(3000 + int(rng() % 3000));
  ctrl(d, "abort");
  ex.eq(status(d, "level"), 0, "status(d, \"level\") == 0");
  d.clear();
  d.preset(Point{});
}

// A hand-made entry at the top of every pacing field (cruise and limit 2^32 - 1: a step
// per clock, the override at 200%, a random length, exit and braking distance) on a long
// line at the largest acceleration: the speed ramps up past half a step per clock and the
// phase saturates (the norm unit's latency holds the steps back) before the abort.
void top_speed(BusMaster& m, MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  const Plan plan = plan_line(Point{}, Point{1 << 22, 1 << 21, -(1 << 20)}, Preload::Half);
  d.set_pacing(~0u, 1u << 24);
  d.set_override(2 * kOverrideOne);
  for (int k = 0; k < 2; ++k) {
    PaceEntry e;
    e.cruise = e.limit = ~0u;
    e.exit = std::uint32_t(rng());
    e.length = std::uint32_t(rng()) | 1u << 31;
    e.brake_exit = std::uint32_t(rng()) >> 1;
    d.queue(plan.pieces[std::size_t(k)].cmd, 0, 0, e);
  }
  m.idle(40000);
  ex.eq(status(d, "busy"), 1, "status(d, \"busy\") == 1");  // still ramping: no stop, no error
  ctrl(d, "abort");
  ex.eq(status(d, "level"), 0, "status(d, \"level\") == 0");
  d.set_override(kOverrideOne);
  d.clear();
  d.preset(Point{});
}

// Pairs of lines queued back to back, the first one's exit 0 under a VMIN above it: the
// pacer lands on VMIN before the first ends, its braking sum keeping what the ramps left
// over (a cruise speed off the acceleration's lattice), and the second accelerates from
// VMIN carrying it into its own braking sum. (A sum off by VMIN's distance of one clock
// seldom moves a braking point: docs/verification.md, "Mutation testing".)
void vmin_corners(MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  Point want = d.position();
  for (int k = 0; k < 4; ++k) {
    const std::uint32_t cruise = (1u << 26) + std::uint32_t(rng() % (1u << 26));  // 1/64 .. 1/32 step per clock
    const std::uint32_t vmin = (1u << 22) + std::uint32_t(rng() % (1u << 24));
    const std::uint32_t accel = (1u << 31) + std::uint32_t(rng() % (1u << 31));  // 2^-17 .. 2^-16 step/clock^2
    d.set_pacing(accel, vmin);
    const Point a{150 + std::int64_t(rng() % 100), std::int64_t(rng() % 100), 0};
    const Point b{-std::int64_t(rng() % 100), 150 + std::int64_t(rng() % 100), 0};
    const Command c1 = plan_line(Point{}, a, Preload::Half).pieces.front().cmd;
    const Command c2 = plan_line(Point{}, b, Preload::Half).pieces.front().cmd;
    d.queue(c1, 0, 0, pace_entries({c1}, cruise, vmin, accel).front());
    d.queue(c2, 0, 0, pace_entries({c2}, cruise, vmin, accel).front());
    d.drain();
    want = want + a + b;
  }
  ex.eq(d.position(), want, "d.position() == want");
}

// Soft stops of a slow line whose X pulses are long (400 clocks at a step per 1,000 or
// more) at the largest acceleration: the speed reaches rest within some 60 clocks of the
// stop, often while the X pulse is out and no other; the flush waits for it.
void soft_stops(BusMaster& m, MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  d.set_timings('x', StageTimings{400, 2, 1, 1});
  d.set_pacing(~0u, 1u << 20);
  const Command c = plan_line(Point{}, Point{3000, 2000, 0}, Preload::Half).pieces.front().cmd;
  for (int k = 0; k < 6; ++k) {
    d.preset(Point{});
    d.queue(c, 0, 0, pace_entries({c}, 1u << 22, 1u << 20, ~0u).front());
    m.idle(2000 + int(rng() % 6000));
    ctrl(d, "soft_stop");
    d.wait_rest();
    ex.eq(status(d, "aborted"), 1, "status(d, \"aborted\") == 1");
    d.clear();
  }
  d.set_timings('x', StageTimings{});
  d.preset(Point{});
}

// IN_FILTER at its longest: the probe's filter at its most clocks, a switch's at its most
// ticks (of 4 clocks: seen 57 to 60 clocks after it differs), then at two ticks of 2^14
// clocks (a tick on the cycle count's high bits): an input held active is seen (INPUTS)
// only after the filter, and released only after it again.
void filter_ranges(MachineSim& t, BusMaster& m, MotionDriver& d, const Expect& outer) {
  const std::uint32_t probe_top = (1u << kFilterWidth) - 1, sw_top = (1u << kSwitchFilterWidth) - 1;
  struct Case {
    const char* in;
    std::uint32_t sw, tick;
    int before, after;  // clocks after the force: not seen yet, seen (a tick's phase is the cycle count's)
  };
  const int p = 1 << 14;
  for (const Case& c : {Case{"probe", 2, 0, int(probe_top) - 64, 128}, Case{"home_z", sw_top, 2, 40, 40},
                        Case{"limit_x_pos", 2, 14, p - 8, p + 16}}) {
    d.set_inputs(0, c.sw, probe_top, 0, c.tick);
    const Expect ex([&](bool ok, const std::string& what) { outer(ok, std::string(c.in) + ": " + what); });
    t.force = [&](MachinePins& pins) { pins = MachinePins::from_bits(pins.bits() | in_bit(c.in)); };
    m.idle(c.before);
    ex.eq(d.read("INPUTS") & in_bit(c.in), 0, "not seen before the filter");
    m.idle(c.after);
    ex.eq(d.read("INPUTS") & in_bit(c.in), in_bit(c.in), "seen after it");
    t.force = nullptr;
    m.idle(c.before);
    ex.eq(d.read("INPUTS") & in_bit(c.in), in_bit(c.in), "still seen before the filter");
    m.idle(c.after);
    ex.eq(d.read("INPUTS") & in_bit(c.in), 0, "released after it");
    d.clear();
  }
  d.set_inputs(0, 2, 2, 0);
}

// The step/dir timings near their maximum on every axis: a move that reverses each
// axis ends on its point.
void timing_ranges(MotionDriver& d, std::mt19937_64& rng, const Expect& ex) {
  constexpr std::uint32_t top = (1u << kTimingWidth) - 1;
  const auto near = [&] { return top - std::uint32_t(rng() % 256); };
  for (const char axis : kAxes) d.set_timings(axis, StageTimings{near(), near(), near(), near()});
  const Point from = d.position();
  queue_unpaced(d, Point{2, 2, -2}, 1);
  queue_unpaced(d, Point{-1, -1, 1}, 1);
  d.drain();
  ex.eq(d.position(), from + Point{1, 1, -1}, "d.position() == from + Point{1, 1, -1}");
  for (const char axis : kAxes) d.set_timings(axis, StageTimings{});
}

}  // namespace

// Every field at its full width, the block compared with the reference model on every
// edge: the registers, the positions, stalled commands, the done count, capacities and integrands at
// the top of the core's contract, the pacer at the top of its ranges, the input filters
// and the step/dir timings at their longest.
void field_ranges(BusTarget& block, const Expect& ex) {
  fresh(block);
  MachineSim t(block, Point{}, MachineSwitches{});
  const auto master = make_master(block.bus(), t, 43, true, 2);
  BusMaster& m = *master;
  MotionDriver d(m, 43);
  std::mt19937_64 rng(43);
  register_ranges(d, rng, ex);
  position_ranges(t, m, d, rng, ex);
  stalled_commands(d, ex);
  uneven_axes(d, ex);
  done_counts(d, ex);
  wide_arcs(m, d, rng, ex);
  wide_lines(d, rng, ex);
  long_line(m, d, rng, ex);
  top_speed(m, d, rng, ex);
  vmin_corners(d, rng, ex);
  soft_stops(m, d, rng, ex);
  filter_ranges(t, m, d, ex);
  timing_ranges(d, rng, ex);
  const MotionDriver::Snapshot last = d.snapshot();  // (SNAP_CYCLE's bits up to the run's length)
  ex(last.cycle > (1u << 18), "last.cycle > (1u << 18)");
}

}  // namespace dda::motion
