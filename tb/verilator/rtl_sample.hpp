// Reads the architectural registers of a Verilated dda_core (--cc or --sc: the root
// classes differ by prefix, the member names are the same) into a CoreSample.
#pragma once

#include "scoreboard.hpp"

namespace dda::rtl {

template <typename Root>
CoreSample sample_root(const Root* r) {
  CoreSample s;
  s.jv_x = r->dda_core__DOT__u_int_x__DOT__jv_q;
  s.jr_x = r->dda_core__DOT__u_int_x__DOT__jr_q;
  s.sum_x = r->dda_core__DOT__u_int_x__DOT__sum;
  s.jv_y = r->dda_core__DOT__u_int_y__DOT__jv_q;
  s.jr_y = r->dda_core__DOT__u_int_y__DOT__jr_q;
  s.sum_y = r->dda_core__DOT__u_int_y__DOT__sum;
  s.cnt_x = r->dda_core__DOT__u_cnt_x__DOT__cnt_q;
  s.cnt_y = r->dda_core__DOT__u_cnt_y__DOT__cnt_q;
  s.cap = r->dda_core__DOT__cap_q;
  s.inc_x_on_x = r->dda_core__DOT__u_int_x__DOT__inc_on_x_q;
  s.inc_x_on_y = r->dda_core__DOT__u_int_x__DOT__inc_on_y_q;
  s.inc_y_on_x = r->dda_core__DOT__u_int_y__DOT__inc_on_x_q;
  s.inc_y_on_y = r->dda_core__DOT__u_int_y__DOT__inc_on_y_q;
  s.step_x = r->dda_core__DOT__step_x_q;
  s.step_y = r->dda_core__DOT__step_y_q;
  s.dir_x = r->dda_core__DOT__dir_x_q;
  s.dir_y = r->dda_core__DOT__dir_y_q;
  s.cdir_x = r->dda_core__DOT__cdir_x_q;
  s.cdir_y = r->dda_core__DOT__cdir_y_q;
  s.state = r->dda_core__DOT__u_ctrl__DOT__state_q;
  s.done = r->dda_core__DOT__u_ctrl__DOT__done_q;
  s.err = r->dda_core__DOT__u_ctrl__DOT__err_q;
  s.iter = r->dda_core__DOT__u_ctrl__DOT__iter_q;
  return s;
}

}  // namespace dda::rtl
