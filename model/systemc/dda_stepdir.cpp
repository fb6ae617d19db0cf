// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_stepdir.hpp"

#include "model/motion/motion_map.hpp"

namespace dda::sc {

namespace {
constexpr std::uint32_t kSat = (1u << motion::kTimingWidth) - 1;
}

dda_stepdir::dda_stepdir(sc_core::sc_module_name name) : sc_core::sc_module(name) {
  SC_METHOD(comb);
  sensitive << flush_i << step_i << dir_i << steplen_i << stepspace_i << dirsetup_i << dirhold_i << step_q << dir_q
            << pend_q << pdir_q << tf_q << ts_q << tag_q;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

dda_stepdir::Wires dda_stepdir::wires() const {
  const std::uint32_t len = steplen_i.read() == 0 ? 1 : steplen_i.read();
  const std::uint32_t space = stepspace_i.read() == 0 ? 1 : stepspace_i.read();
  Wires w{};
  w.fall = step_q.read() && tf_q.read() >= len;
  const bool dir_ok = step_q.read() ? (w.fall && dirhold_i.read() == 0) : tf_q.read() >= dirhold_i.read();
  w.change = pend_q.read() && pdir_q.read() != dir_q.read() && dir_ok;
  w.dir_d = w.change ? pdir_q.read() : dir_q.read();
  const std::uint32_t ts_now = w.change ? 0 : ts_q.read();
  w.rise = pend_q.read() && !step_q.read() && tf_q.read() >= space && w.dir_d == pdir_q.read() &&
           ts_now >= dirsetup_i.read() && !flush_i.read();
  const std::uint32_t tf = tf_q.read(), ts = ts_q.read();
  w.step_d = w.rise || (step_q.read() && !w.fall);
  w.tf_d = (w.rise || w.fall) ? 1 : tf == kSat ? tf : tf + 1;
  w.ts_d = w.change ? 1 : ts == kSat ? ts : ts + 1;
  w.pend_d = (pend_q.read() && !w.rise) || step_i.read();
  w.pdir_d = step_i.read() ? dir_i.read() : pdir_q.read();
  // Would a step waiting after this edge leave on the next one?
  if (w.pdir_d != w.dir_d) {
    w.rise_n = !w.step_d && w.tf_d >= space && w.tf_d >= dirhold_i.read() && dirsetup_i.read() == 0;
  } else {
    w.rise_n = !w.step_d && w.tf_d >= space && w.ts_d >= dirsetup_i.read();
  }
  return w;
}

void dda_stepdir::comb() {
  const Wires w = wires();
  step_o.write(step_q.read());
  dir_o.write(dir_q.read());
  hold_o.write(w.pend_d && !w.rise_n);
  wait_o.write(w.pend_d);
  tag_left_o.write(tag_q.read() && !w.rise);
  rise_o.write(w.rise);
  rise_dir_o.write(pdir_q.read());
  busy_o.write(step_i.read() || pend_q.read() || step_q.read());
  pend_o.write(pend_q.read());
  pdir_o.write(pdir_q.read());
}

void dda_stepdir::seq() {
  if (!rst_ni.read()) {
    step_q.write(false);
    dir_q.write(false);
    pend_q.write(false);
    pdir_q.write(false);
    tf_q.write(kSat);
    ts_q.write(kSat);
    tag_q.write(false);
    return;
  }
  const Wires w = wires();
  step_q.write(w.step_d);
  dir_q.write(w.dir_d);
  tf_q.write(w.tf_d);
  ts_q.write(w.ts_d);
  pend_q.write(!flush_i.read() && w.pend_d);
  pdir_q.write(w.pdir_d);
  tag_q.write(!flush_i.read() && (tag_i.read() ? w.pend_d : tag_q.read() && !w.rise));
}

}  // namespace dda::sc
