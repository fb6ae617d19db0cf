// SPDX-License-Identifier: Apache-2.0
// The step/dir stage of the motion block's reference model (motion_model.hpp): one edge
// of the stage that turns the core's steps into pulses with their timings
// (rtl/dda_stepdir.v), and its timing diagram for docs/design.md.
#include <string>
#include <vector>

#include "model/motion/motion_model.hpp"

namespace dda::motion {

namespace {

// The largest value of a timing register: the saturating counters stop there.
constexpr std::uint32_t kTimingMax = (std::uint32_t{1} << kTimingWidth) - 1;

}  // namespace

StageRegs stage_reset() {
  StageRegs r;
  r.tf = r.ts = kTimingMax;
  return r;
}

StageEdge stage_edge(const StageRegs& r, const StageTimings& t, bool step_in, bool dir_in, bool tag_in, bool flush) {
  const std::uint32_t sat = kTimingMax;
  const std::uint32_t len = t.steplen == 0 ? 1 : t.steplen, space = t.stepspace == 0 ? 1 : t.stepspace;
  const bool fall = r.step && r.tf >= len;
  const bool dir_ok = r.step ? (fall && t.dirhold == 0) : r.tf >= t.dirhold;
  const bool change = r.pend && r.pdir != r.dir && dir_ok;
  const bool dir_d = change ? r.pdir : r.dir;
  const std::uint32_t ts_now = change ? 0 : r.ts;
  const bool rise = r.pend && !r.step && r.tf >= space && dir_d == r.pdir && ts_now >= t.dirsetup && !flush;
  StageEdge e;
  const bool pend_d = (r.pend && !rise) || step_in;
  e.rise = rise;
  e.rise_dir = r.pdir;
  e.wait = pend_d;
  e.tag_left = r.tag && !rise;
  e.busy = step_in || r.pend || r.step;
  e.next.step = rise || (r.step && !fall);
  e.next.dir = dir_d;
  e.next.tf = (rise || fall) ? 1 : r.tf == sat ? sat : r.tf + 1;
  e.next.ts = change ? 1 : r.ts == sat ? sat : r.ts + 1;
  e.next.pend = !flush && pend_d;
  e.next.pdir = step_in ? dir_in : r.pdir;
  e.next.tag = !flush && (tag_in ? pend_d : r.tag && !rise);
  // Hold the core unless a step waiting after this edge leaves on the next one.
  const StageRegs& n = e.next;
  const bool turn_n = n.pdir != n.dir;
  const bool rise_n = !n.step && n.tf >= space && (turn_n ? n.tf >= t.dirhold && t.dirsetup == 0 : n.ts >= t.dirsetup);
  e.hold = pend_d && !rise_n;
  return e;
}

std::string stage_diagram() {
  const StageTimings t{3, 2, 2, 1};
  const int edges = 12;
  StageRegs r = stage_reset();
  // The core's step register after each edge: + set on edge 0, then - on the first edge
  // whose cycle the stage does not hold (the core iterates only then).
  std::vector<int> core(edges + 2, 0);  // 0 none, 1 +, -1 -
  core[0] = 1;
  bool minus_done = false;
  std::string row_core = "core step ", row_hold = "core held ", row_pend = "pend_q    ", row_step = "step out  ",
              row_dir = "dir out   ", row_edge = "edge      ";
  const auto cell = [](std::string& row, const std::string& v) { row += v + std::string(4 - v.size(), ' '); };
  cell(row_edge, "0");
  cell(row_core, "+");
  cell(row_hold, "");
  cell(row_pend, "0");
  cell(row_step, "_");
  cell(row_dir, "+");
  for (int e = 1; e <= edges; ++e) {
    const bool in = core[std::size_t(e - 1)] != 0, in_dir = core[std::size_t(e - 1)] < 0;
    const StageEdge x = stage_edge(r, t, in, in_dir, false, false);
    if (!minus_done && !x.hold) {
      core[std::size_t(e)] = -1;
      minus_done = true;
    }
    r = x.next;
    cell(row_edge, std::to_string(e));
    cell(row_core, core[std::size_t(e)] > 0 ? "+" : core[std::size_t(e)] < 0 ? "-" : "");
    cell(row_hold, x.hold ? "1" : "");
    cell(row_pend, r.pend ? "1" : "0");
    cell(row_step, r.step ? "#" : "_");
    cell(row_dir, r.dir ? "-" : "+");
  }
  std::string o;
  for (std::string* row : {&row_edge, &row_core, &row_hold, &row_pend, &row_step, &row_dir}) {
    while (!row->empty() && row->back() == ' ') row->pop_back();
    o += *row + "\n";
  }
  return o;
}

}  // namespace dda::motion
