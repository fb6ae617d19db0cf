// SPDX-License-Identifier: Apache-2.0
// The datapath: iteration records around the one next-state function (datapath.hpp).
#include "datapath/datapath.hpp"

namespace dda {

Datapath::Datapath(const Command& cmd, Point start) : cmd_(cmd), regs_(initial_regs(cmd)), pos_(start) {}

Iteration Datapath::iterate() {
  Iteration it;
  it.jv_x = regs_.jv_x;
  it.jv_y = regs_.jv_y;
  const StepOut o = next_state(cmd_, regs_);
  move(o);
  it.iter = iter_;
  it.active_x = o.active_x;
  it.active_y = o.active_y;
  it.sum_x = o.sum_x;
  it.sum_y = o.sum_y;
  it.step_x = o.step_x;
  it.step_y = o.step_y;
  it.after = regs_;
  it.pos = pos_;
  return it;
}

RegState initial_regs(const Command& c) {
  RegState r;
  r.jv_x = c.jv_x;
  r.jv_y = c.jv_y;
  r.jr_x = c.jr_x;
  r.jr_y = c.jr_y;
  r.cnt_x = c.cnt_x;
  r.cnt_y = c.cnt_y;
  return r;
}

}  // namespace dda
