// SPDX-License-Identifier: Apache-2.0
#include "motion/stepdir_monitor.hpp"

#include <algorithm>
#include <string>

#include "datapath/errors.hpp"

namespace dda::motion {

void StepDirChecker::load_timings(Axis& x, const BlockRegs& r, int a) {
  const std::string n = a == 0 ? "x" : "y";
  const auto reg = [&](const std::string& f) { return r[breg(f + "_" + n + "_q")]; };
  x.len = std::max<std::uint64_t>(reg("steplen"), 1);
  x.space = std::max<std::uint64_t>(reg("stepspace"), 1);
  x.setup = reg("dirsetup");
  x.hold = reg("dirhold");
}

void StepDirChecker::check_axis(const BlockRegs& r, int a, bool step, bool dir, bool preset, std::uint32_t pos) {
  Axis& x = ax_[std::size_t(a)];
  const std::string n = a == 0 ? "x" : "y";
  const std::uint64_t len = x.len, space = x.space, setup = x.setup, hold = x.hold;
  const auto fail = [&](const std::string& what) {
    throw GuardError("step/dir monitor, axis " + n + ", cycle " + std::to_string(cycle_) + ": " + what);
  };
  const bool rise = step && !x.step, fall = !step && x.step, turn = dir != x.dir;
  Shortest& sh = short_[std::size_t(a)];
  if (turn) {
    if (x.step && step) fail("the direction changed during a pulse");
    const std::uint64_t after = fall ? 0 : x.since_fall;
    if (x.seen_fall) sh.hold = std::min(sh.hold, after);
    x.turned = true;
    if (x.seen_fall && after < hold) {
      fail("the direction changed " + std::to_string(after) + " cycles after a falling step edge, dirhold " +
           std::to_string(hold));
    }
  }
  if (rise) {
    const std::uint64_t stable = turn ? 0 : x.dir_cycles;
    if (x.turned) sh.setup = std::min(sh.setup, stable);
    if (x.seen_fall) sh.low = std::min(sh.low, x.level_cycles);
    x.turned = false;
    if ((x.seen_dir || turn) && stable < setup) {
      fail("a rising step edge " + std::to_string(stable) + " cycles after a direction change, dirsetup " +
           std::to_string(setup));
    }
    if (x.seen_fall && x.level_cycles < space) {
      fail("a pulse " + std::to_string(x.level_cycles) + " cycles after the last one, stepspace " +
           std::to_string(space));
    }
    ++pulses_[std::size_t(a)];
    x.moved += dir ? -1 : 1;
  }
  if (fall) sh.high = std::min(sh.high, x.level_cycles);
  if (fall && x.level_cycles < len) {
    fail("a pulse " + std::to_string(x.level_cycles) + " cycles long, steplen " + std::to_string(len));
  }
  // The timers, counted in cycles sampled after each edge.
  x.level_cycles = (rise || fall) ? 1 : x.level_cycles + 1;
  x.dir_cycles = turn ? 1 : x.dir_cycles + 1;
  x.since_fall = fall ? 1 : x.since_fall + 1;
  x.seen_fall = x.seen_fall || fall;
  x.seen_dir = x.seen_dir || turn;
  x.step = step;
  x.dir = dir;
  load_timings(x, r, a);
  // The position counter moved by exactly the pulses that went out.
  if (preset) {
    x.pos0 = pos - std::uint32_t(rise ? (dir ? -1 : 1) : 0);
    x.moved = rise ? (dir ? -1 : 1) : 0;
  }
  if (std::uint32_t(x.pos0 + std::uint32_t(x.moved)) != pos) {
    fail("the position counter is " + std::to_string(std::int32_t(pos)) + ", the pulses that went out make it " +
         std::to_string(std::int32_t(x.pos0 + std::uint32_t(x.moved))));
  }
}

void StepDirChecker::edge(const BusIn& bus, bool rst_n, const BlockOutputs& o, const BlockRegs& r) {
  ++cycle_;
  const std::uint64_t pol = r[breg("polarity_q")];
  const auto inv = [&](std::string_view f) { return ((pol >> field_of("POLARITY", f).lsb) & 1u) != 0; };
  const bool step_x = o.step_x != inv("step_x"), dir_x = o.dir_x != inv("dir_x");
  const bool step_y = o.step_y != inv("step_y"), dir_y = o.dir_y != inv("dir_y");
  const auto pos_x = std::uint32_t(r[breg("pos_x_q")]), pos_y = std::uint32_t(r[breg("pos_y_q")]);
  if (!started_ || !rst_n) {  // the outputs and counters start again
    started_ = true;
    ax_ = {};
    ax_[0].step = step_x;
    ax_[0].dir = dir_x;
    ax_[0].pos0 = pos_x;
    ax_[1].step = step_y;
    ax_[1].dir = dir_y;
    ax_[1].pos0 = pos_y;
    load_timings(ax_[0], r, 0);
    load_timings(ax_[1], r, 1);
    return;
  }
  // A write the block took on this edge: it acknowledges it after the edge.
  const std::uint32_t adr = bus.adr & ((1u << kAddrWidth) - 1) & ~3u;
  const bool wrote = bus.cyc && bus.stb && bus.we && o.ack;
  check_axis(r, 0, step_x, dir_x, wrote && adr == reg_offset("POS_X"), pos_x);
  check_axis(r, 1, step_y, dir_y, wrote && adr == reg_offset("POS_Y"), pos_y);
}

}  // namespace dda::motion
