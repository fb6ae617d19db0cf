// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_ctrl.hpp"

namespace dda::sc {

namespace {
constexpr unsigned kIdle = unsigned(hw::State::Idle);
constexpr unsigned kRun = unsigned(hw::State::Run);
}  // namespace

void dda_ctrl::comb() {
  const bool idle = state_q.read() == kIdle;
  const bool run_ce = state_q.read() == kRun && ce_i.read();
  const bool fin = run_ce && !active_x_i.read() && !active_y_i.read() && !active_z_i.read();
  const bool st = run_ce && !fin && !can_x_i.read() && !can_y_i.read() && !can_z_i.read();
  const bool it = run_ce && !fin && !st;
  // The command ends on this edge: the next one may load on the same edge (back to back).
  const bool ending = fin || (it && last_x_i.read() && last_y_i.read() && last_z_i.read());
  finished.write(fin);
  stalled.write(st);
  finishing.write(ending);
  cmd_ready_o.write(idle || ending);
  busy_o.write(!idle);
  load_o.write((idle || ending) && cmd_valid_i.read());
  iterate_o.write(it);
  done_o.write(done_q.read());
  err_o.write(err_q.read());
  iter_o.write(iter_q.read());
}

void dda_ctrl::seq() {
  if (!rst_ni.read()) {
    state_q.write(kIdle);
    done_q.write(false);
    err_q.write(false);
    iter_q.write(false);
    return;
  }
  unsigned state = state_q.read();
  if (load_o.read()) {
    state = kRun;
  } else if (finishing.read() || stalled.read()) {
    state = kIdle;
  }
  state_q.write(state);
  done_q.write(finishing.read());
  err_q.write(stalled.read());
  iter_q.write(iterate_o.read());
}

void dda_ctrl::trace(sc_core::sc_trace_file* tf, const std::string& p) const {
  sc_core::sc_trace(tf, state_q, p + ".state_q");
  sc_core::sc_trace(tf, done_q, p + ".done_q");
  sc_core::sc_trace(tf, err_q, p + ".err_q");
  sc_core::sc_trace(tf, iter_q, p + ".iter_q");
  sc_core::sc_trace(tf, finished, p + ".finished");
  sc_core::sc_trace(tf, stalled, p + ".stalled");
  sc_core::sc_trace(tf, finishing, p + ".finishing");
}

}  // namespace dda::sc
