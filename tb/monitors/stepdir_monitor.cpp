// SPDX-License-Identifier: Apache-2.0
#include "tb/monitors/stepdir_monitor.hpp"

#include <algorithm>
#include <string>

#include "model/datapath/errors.hpp"

namespace dda::motion {

void StepDirChecker::load_timings(Axis& x, const BlockRegs& r, int a) {
  const std::string n(1, kAxes[std::size_t(a)]);
  const auto reg = [&](const std::string& f) { return r[breg(f + "_" + n + "_q")]; };
  x.len = std::max<std::uint64_t>(reg("steplen"), 1);
  x.space = std::max<std::uint64_t>(reg("stepspace"), 1);
  x.setup = reg("dirsetup");
  x.hold = reg("dirhold");
}

void StepDirChecker::check_axis(const BlockRegs& r, int a, bool step, bool dir, bool preset, std::uint32_t pos) {
  Axis& x = ax_[std::size_t(a)];
  const std::string n(1, kAxes[std::size_t(a)]);
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
  const std::array<bool, kAxes.size()> steps{o.step_x, o.step_y, o.step_z}, dirs{o.dir_x, o.dir_y, o.dir_z};
  const bool restart = !started_ || !rst_n;  // the outputs and counters start again
  started_ = true;
  if (restart) ax_ = {};
  // A write the block took on this edge: it acknowledges it after the edge.
  const std::uint32_t adr = bus.adr & ((1u << kAddrWidth) - 1) & ~3u;
  const bool wrote = bus.cyc && bus.stb && bus.we && o.ack;
  for (std::size_t a = 0; a < kAxes.size(); ++a) {
    const std::string n(1, kAxes[a]), up(1, char(kAxes[a] - 'a' + 'A'));
    const bool step = steps[a] != inv("step_" + n), dir = dirs[a] != inv("dir_" + n);
    const auto pos = std::uint32_t(r[breg("pos_" + n + "_q")]);
    if (restart) {
      ax_[a].step = step;
      ax_[a].dir = dir;
      ax_[a].pos0 = pos;
      load_timings(ax_[a], r, int(a));
    } else {
      check_axis(r, int(a), step, dir, wrote && adr == reg_offset("POS_" + up), pos);
    }
  }
}

}  // namespace dda::motion
