#include "dda_ctrl.h"

namespace dda::sc {

namespace {
constexpr unsigned kIdle = unsigned(hw::State::Idle);
constexpr unsigned kRun = unsigned(hw::State::Run);
}  // namespace

void dda_ctrl::comb() {
  const bool idle = state_q.read() == kIdle;
  const bool run_ce = state_q.read() == kRun && ce_i.read();
  const bool fin = run_ce && !active_x_i.read() && !active_y_i.read();
  const bool st = run_ce && !fin && !can_x_i.read() && !can_y_i.read();
  finished.write(fin);
  stalled.write(st);
  cmd_ready_o.write(idle);
  busy_o.write(!idle);
  load_o.write(idle && cmd_valid_i.read());
  iterate_o.write(run_ce && !fin && !st);
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
  bool done = false, err = false, iter = false;
  unsigned state = state_q.read();
  if (state == kIdle) {
    if (cmd_valid_i.read()) state = kRun;
  } else if (ce_i.read()) {
    if (finished.read()) {
      state = kIdle;
      done = true;
    } else if (stalled.read()) {
      state = kIdle;
      err = true;
    } else {
      iter = true;
      if (last_x_i.read() && last_y_i.read()) {
        state = kIdle;
        done = true;
      }
    }
  }
  state_q.write(state);
  done_q.write(done);
  err_q.write(err);
  iter_q.write(iter);
}

void dda_ctrl::trace(sc_core::sc_trace_file* tf, const std::string& p) const {
  sc_core::sc_trace(tf, state_q, p + ".state_q");
  sc_core::sc_trace(tf, done_q, p + ".done_q");
  sc_core::sc_trace(tf, err_q, p + ".err_q");
  sc_core::sc_trace(tf, iter_q, p + ".iter_q");
  sc_core::sc_trace(tf, finished, p + ".finished");
  sc_core::sc_trace(tf, stalled, p + ".stalled");
}

}  // namespace dda::sc
