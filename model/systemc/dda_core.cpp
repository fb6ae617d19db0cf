// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_core.hpp"

namespace dda::sc {

namespace {
template <typename T>
T field(const cmd_t& cmd, std::string_view name) {
  const int lsb = hw::cmd_offset(name);
  int width = 0;
  for (const auto& f : hw::kCmdFields) {
    if (f.name == name) width = f.width;
  }
  return T(cmd.range(lsb + width - 1, lsb).to_uint64());
}
}  // namespace

dda_core::dda_core(sc_core::sc_module_name name, IntegratorFactory make_integrator) : sc_core::sc_module(name) {
  if (!make_integrator) {
    make_integrator = [](const char* n) { return std::make_unique<dda_integrator>(n); };
  }
  u_int_x = make_integrator("u_int_x");
  u_int_y = make_integrator("u_int_y");

  for (auto* integ : {u_int_x.get(), u_int_y.get()}) {
    integ->clk_i(clk_i);
    integ->rst_ni(rst_ni);
    integ->load_i(load);
    integ->iterate_i(iterate);
    integ->cap_i(cap_q);
    integ->ovf_x_i(ovf_x);
    integ->ovf_y_i(ovf_y);
  }
  u_int_x->active_i(active_x);
  u_int_x->jv_i(cmd_jv_x);
  u_int_x->jr_i(cmd_jr_x);
  u_int_x->inc_on_x_i(cmd_inc_x_on_x);
  u_int_x->inc_on_y_i(cmd_inc_x_on_y);
  u_int_x->ovf_o(ovf_x);
  u_int_x->can_o(can_x);
  u_int_x->jv_o(jv_x);
  u_int_y->active_i(active_y);
  u_int_y->jv_i(cmd_jv_y);
  u_int_y->jr_i(cmd_jr_y);
  u_int_y->inc_on_x_i(cmd_inc_y_on_x);
  u_int_y->inc_on_y_i(cmd_inc_y_on_y);
  u_int_y->ovf_o(ovf_y);
  u_int_y->can_o(can_y);
  u_int_y->jv_o(jv_y);

  u_cnt_x.clk_i(clk_i);
  u_cnt_x.rst_ni(rst_ni);
  u_cnt_x.load_i(load);
  u_cnt_x.iterate_i(iterate);
  u_cnt_x.cnt_i(cmd_cnt_x);
  u_cnt_x.dec_i(ovf_x);
  u_cnt_x.active_o(active_x);
  u_cnt_x.last_o(last_x);
  u_cnt_y.clk_i(clk_i);
  u_cnt_y.rst_ni(rst_ni);
  u_cnt_y.load_i(load);
  u_cnt_y.iterate_i(iterate);
  u_cnt_y.cnt_i(cmd_cnt_y);
  u_cnt_y.dec_i(ovf_y);
  u_cnt_y.active_o(active_y);
  u_cnt_y.last_o(last_y);

  u_ctrl.clk_i(clk_i);
  u_ctrl.rst_ni(rst_ni);
  u_ctrl.cmd_valid_i(cmd_valid_i);
  u_ctrl.ce_i(ce_i);
  u_ctrl.active_x_i(active_x);
  u_ctrl.active_y_i(active_y);
  u_ctrl.can_x_i(can_x);
  u_ctrl.can_y_i(can_y);
  u_ctrl.last_x_i(last_x);
  u_ctrl.last_y_i(last_y);
  bind_third_axis();
  u_ctrl.cmd_ready_o(cmd_ready_o);
  u_ctrl.load_o(load);
  u_ctrl.iterate_o(iterate);
  u_ctrl.busy_o(busy_o);
  u_ctrl.done_o(done_o);
  u_ctrl.err_o(err_o);
  u_ctrl.iter_o(iter_o);

  SC_METHOD(decode);
  sensitive << cmd_i;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
  SC_METHOD(outputs);
  sensitive << step_x_q << step_y_q << step_z_q << dir_x_q << dir_y_q << dir_z_q;
  SC_METHOD(norm);
  sensitive << active_x << active_y << active_z << jv_x << jv_y << jv_z << cap_q << cap_z;
}

void dda_core::bind_third_axis() {
  u_lin_z.clk_i(clk_i);
  u_lin_z.rst_ni(rst_ni);
  u_lin_z.load_i(load);
  u_lin_z.iterate_i(iterate);
  u_lin_z.active_i(active_z);
  u_lin_z.jv_i(cmd_jv_z);
  u_lin_z.jr_i(cmd_jr_z);
  u_lin_z.cap_i(cmd_cap_z);
  u_lin_z.ovf_o(ovf_z);
  u_lin_z.can_o(can_z);
  u_lin_z.jv_o(jv_z);
  u_lin_z.cap_o(cap_z);
  u_cnt_z.clk_i(clk_i);
  u_cnt_z.rst_ni(rst_ni);
  u_cnt_z.load_i(load);
  u_cnt_z.iterate_i(iterate);
  u_cnt_z.cnt_i(cmd_cnt_z);
  u_cnt_z.dec_i(ovf_z);
  u_cnt_z.active_o(active_z);
  u_cnt_z.last_o(last_z);
  u_ctrl.active_z_i(active_z);
  u_ctrl.can_z_i(can_z);
  u_ctrl.last_z_i(last_z);
}

void dda_core::decode() {
  const cmd_t c = cmd_i.read();
  cmd_jv_x.write(field<acc_t>(c, "jv_x"));
  cmd_jv_y.write(field<acc_t>(c, "jv_y"));
  cmd_jr_x.write(field<acc_t>(c, "jr_x"));
  cmd_jr_y.write(field<acc_t>(c, "jr_y"));
  cmd_cap.write(field<acc_t>(c, "cap"));
  cmd_cnt_x.write(field<cnt_t>(c, "cnt_x"));
  cmd_cnt_y.write(field<cnt_t>(c, "cnt_y"));
  cmd_dir_x.write(field<unsigned>(c, "dir_x") != 0);
  cmd_dir_y.write(field<unsigned>(c, "dir_y") != 0);
  cmd_inc_x_on_x.write(field<acc_t>(c, "inc_x_on_x"));
  cmd_inc_x_on_y.write(field<acc_t>(c, "inc_x_on_y"));
  cmd_inc_y_on_x.write(field<acc_t>(c, "inc_y_on_x"));
  cmd_inc_y_on_y.write(field<acc_t>(c, "inc_y_on_y"));
  cmd_jv_z.write(field<acc_t>(c, "jv_z"));
  cmd_jr_z.write(field<acc_t>(c, "jr_z"));
  cmd_cap_z.write(field<acc_t>(c, "cap_z"));
  cmd_cnt_z.write(field<cnt_t>(c, "cnt_z"));
  cmd_dir_z.write(field<unsigned>(c, "dir_z") != 0);
}

void dda_core::seq() {
  if (!rst_ni.read()) {
    cap_q.write(0);
    cdir_x_q.write(false);
    cdir_y_q.write(false);
    cdir_z_q.write(false);
    dir_x_q.write(false);
    dir_y_q.write(false);
    dir_z_q.write(false);
    step_x_q.write(false);
    step_y_q.write(false);
    step_z_q.write(false);
    return;
  }
  if (load.read()) {
    cap_q.write(cmd_cap.read());
    cdir_x_q.write(cmd_dir_x.read());
    cdir_y_q.write(cmd_dir_y.read());
    cdir_z_q.write(cmd_dir_z.read());
  }
  // A step carries the direction of the command that made it (see the RTL).
  const bool sx = iterate.read() && ovf_x.read(), sy = iterate.read() && ovf_y.read();
  const bool sz = iterate.read() && ovf_z.read();
  step_x_q.write(sx);
  step_y_q.write(sy);
  step_z_q.write(sz);
  if (sx) dir_x_q.write(cdir_x_q.read());
  if (sy) dir_y_q.write(cdir_y_q.read());
  if (sz) dir_z_q.write(cdir_z_q.read());
}

void dda_core::outputs() {
  step_x_o.write(step_x_q.read());
  step_y_o.write(step_y_q.read());
  dir_x_o.write(dir_x_q.read());
  dir_y_o.write(dir_y_q.read());
  step_z_o.write(step_z_q.read());
  dir_z_o.write(dir_z_q.read());
}

void dda_core::norm() {
  const auto v = [](bool active, const acc_t& jv) {
    return active && !jv[hw::kAccWidth - 1] ? std::uint64_t(jv.to_uint64()) : std::uint64_t{0};
  };
  norm_v_x_o.write(v(active_x.read(), jv_x.read()));
  norm_v_y_o.write(v(active_y.read(), jv_y.read()));
  norm_v_z_o.write(v(active_z.read(), jv_z.read()));
  norm_cap_o.write(cap_q.read().to_uint64());
  norm_cap_z_o.write(cap_z.read().to_uint64());
}

void dda_core::trace(sc_core::sc_trace_file* tf) const {
  sc_core::sc_trace(tf, clk_i, "clk_i");
  sc_core::sc_trace(tf, rst_ni, "rst_ni");
  sc_core::sc_trace(tf, ce_i, "ce_i");
  sc_core::sc_trace(tf, cmd_valid_i, "cmd_valid_i");
  sc_core::sc_trace(tf, cmd_ready_o, "cmd_ready_o");
  sc_core::sc_trace(tf, cap_q, "cap_q");
  sc_core::sc_trace(tf, cdir_x_q, "cdir_x_q");
  sc_core::sc_trace(tf, cdir_y_q, "cdir_y_q");
  sc_core::sc_trace(tf, cdir_z_q, "cdir_z_q");
  sc_core::sc_trace(tf, dir_x_q, "dir_x_q");
  sc_core::sc_trace(tf, dir_y_q, "dir_y_q");
  sc_core::sc_trace(tf, dir_z_q, "dir_z_q");
  sc_core::sc_trace(tf, step_x_q, "step_x_q");
  sc_core::sc_trace(tf, step_y_q, "step_y_q");
  sc_core::sc_trace(tf, step_z_q, "step_z_q");
  sc_core::sc_trace(tf, busy_o, "busy_o");
  sc_core::sc_trace(tf, load, "load");
  sc_core::sc_trace(tf, iterate, "iterate");
  u_int_x->trace(tf, "u_int_x");
  u_int_y->trace(tf, "u_int_y");
  u_cnt_x.trace(tf, "u_cnt_x");
  u_lin_z.trace(tf, "u_lin_z");
  u_cnt_y.trace(tf, "u_cnt_y");
  u_cnt_z.trace(tf, "u_cnt_z");
  u_ctrl.trace(tf, "u_ctrl");
}

}  // namespace dda::sc
