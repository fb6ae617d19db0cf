// SPDX-License-Identifier: Apache-2.0
#include "tb/monitors/stepdir_monitor.hpp"

#include <algorithm>
#include <string>

#include "model/datapath/errors.hpp"

namespace dda::motion {

namespace {
// An axis' registers and bits, found once (the checker runs on every edge).
struct AxisIndex {
  std::size_t steplen, stepspace, dirsetup, dirhold, pos;
  int step_pol, dir_pol;  // POLARITY's bits
  std::uint32_t pos_offset;
};
const AxisIndex& axis_index(std::size_t a) {
  static const auto index = [] {
    std::array<AxisIndex, kAxes.size()> t{};
    for (std::size_t k = 0; k < kAxes.size(); ++k) {
      const std::string n(1, kAxes[k]), up(1, char(kAxes[k] - 'a' + 'A'));
      t[k] = {
          breg("steplen_" + n + "_q"),          breg("stepspace_" + n + "_q"), breg("dirsetup_" + n + "_q"),
          breg("dirhold_" + n + "_q"),          breg("pos_" + n + "_q"),       field_of("POLARITY", "step_" + n).lsb,
          field_of("POLARITY", "dir_" + n).lsb, reg_offset("POS_" + up)};
    }
    return t;
  }();
  return index[a];
}
}  // namespace

void StepDirChecker::load_timings(Axis& x, const BlockRegs& r, int a) {
  const AxisIndex& i = axis_index(std::size_t(a));
  x.len = std::max<std::uint64_t>(r[i.steplen], 1);
  x.space = std::max<std::uint64_t>(r[i.stepspace], 1);
  x.setup = r[i.dirsetup];
  x.hold = r[i.dirhold];
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
  const std::uint64_t pol = r[DDA_BREG("polarity_q")];
  const auto inv = [&](int bit) { return ((pol >> bit) & 1u) != 0; };
  const std::array<bool, kAxes.size()> steps{o.step_x, o.step_y, o.step_z}, dirs{o.dir_x, o.dir_y, o.dir_z};
  const bool restart = !started_ || !rst_n;  // the outputs and counters start again
  started_ = true;
  if (restart) ax_ = {};
  // A write the block took on this edge: it acknowledges it after the edge.
  const std::uint32_t adr = bus.adr & ((1u << kAddrWidth) - 1) & ~3u;
  const bool wrote = bus.cyc && bus.stb && bus.we && o.ack;
  for (std::size_t a = 0; a < kAxes.size(); ++a) {
    const AxisIndex& i = axis_index(a);
    const bool step = steps[a] != inv(i.step_pol), dir = dirs[a] != inv(i.dir_pol);
    const auto pos = std::uint32_t(r[i.pos]);
    if (restart) {
      ax_[a].step = step;
      ax_[a].dir = dir;
      ax_[a].pos0 = pos;
      load_timings(ax_[a], r, int(a));
    } else {
      check_axis(r, int(a), step, dir, wrote && adr == i.pos_offset, pos);
    }
  }
}

}  // namespace dda::motion
