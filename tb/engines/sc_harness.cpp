// SPDX-License-Identifier: Apache-2.0
#include "tb/engines/sc_harness.hpp"

#include <cstdio>

#include "model/datapath/hw_command.hpp"

namespace dda::sc {

ScHarness::ScHarness(const std::string& vcd, dda_core::IntegratorFactory factory) {
  // SystemC prints informational reports (e.g. the trace time unit) on stdout, which
  // would mix with the rows a command prints there.
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  core_ = std::make_unique<dda_core>("dut", std::move(factory));
  core_->clk_i(clk_);
  core_->rst_ni(rst_n_);
  core_->ce_i(ce_);
  core_->cmd_valid_i(cmd_valid_);
  core_->cmd_ready_o(cmd_ready_);
  core_->cmd_i(cmd_);
  core_->step_x_o(step_x_);
  core_->dir_x_o(dir_x_);
  core_->step_y_o(step_y_);
  core_->dir_y_o(dir_y_);
  core_->step_z_o(step_z_);
  core_->dir_z_o(dir_z_);
  core_->busy_o(busy_);
  core_->done_o(done_);
  core_->err_o(err_);
  core_->iter_o(iter_);
  core_->norm_v_x_o(norm_v_x_);
  core_->norm_v_y_o(norm_v_y_);
  core_->norm_v_z_o(norm_v_z_);
  core_->norm_cap_o(norm_cap_);
  core_->norm_cap_z_o(norm_cap_z_);
  sampler_ = std::make_unique<ScSampler>(core_->name(), hw::signal_table());
  if (!vcd.empty()) {
    // SystemC appends ".vcd" to the name it is given; close_trace() moves the file to
    // exactly the requested name.
    vcd_ = vcd;
    tf_ = sc_core::sc_create_vcd_trace_file(vcd.c_str());
    tf_->set_time_unit(1, sc_core::SC_NS);
    core_->trace(tf_);
    sc_core::sc_trace(tf_, step_x_, "step_x_o");
    sc_core::sc_trace(tf_, dir_x_, "dir_x_o");
    sc_core::sc_trace(tf_, step_y_, "step_y_o");
    sc_core::sc_trace(tf_, dir_y_, "dir_y_o");
    sc_core::sc_trace(tf_, step_z_, "step_z_o");
    sc_core::sc_trace(tf_, dir_z_, "dir_z_o");
    sc_core::sc_trace(tf_, done_, "done_o");
    sc_core::sc_trace(tf_, err_, "err_o");
    sc_core::sc_trace(tf_, iter_, "iter_o");
  }
}

ScHarness::~ScHarness() {
  try {
    close_trace();
  } catch (const std::exception&) {
    // Destructors do not throw; the engine calls close_trace() itself to report it.
  }
}

void ScHarness::close_trace() {
  if (tf_) {
    sc_core::sc_close_vcd_trace_file(tf_);
    tf_ = nullptr;
    const std::string written = vcd_ + ".vcd";
    if (std::rename(written.c_str(), vcd_.c_str()) != 0) {
      throw GuardError("cannot write the waveform '" + vcd_ + "'");
    }
  }
}

cmd_t command_bits(const CmdFields& fields) {
  const auto words = hw::pack_fields(fields);
  cmd_t c;
  for (std::size_t i = 0; i < words.size(); ++i) {
    for (int b = 0; b < 32 && int(i * 32) + b < hw::kCmdWidth; ++b) {
      c[int(i * 32) + b] = bool((words[i] >> b) & 1u);
    }
  }
  return c;
}

void ScHarness::apply(const CoreInputs& in, bool cmd_changed) {
  rst_n_.write(in.rst_n);
  ce_.write(in.ce);
  cmd_valid_.write(in.cmd_valid);
  if (cmd_changed) cmd_.write(command_bits(in.cmd));
}

void settle() {
  // sc_start(SC_ZERO_TIME) runs one delta cycle; run them until nothing is pending, so
  // input writes have reached every combinational output (cmd_ready_o depends on ce_i).
  // Nothing pending (after the first start): already settled, and SystemC would warn.
  if (sc_core::sc_get_status() != sc_core::SC_ELABORATION && !sc_core::sc_pending_activity_at_current_time()) return;
  do {
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
  } while (sc_core::sc_pending_activity_at_current_time());
}

bool ScHarness::cmd_ready() {
  settle();
  return cmd_ready_.read();
}

bool ScHarness::edge() {
  const bool ready = cmd_ready();
  // The clock's rising edges are at 5, 15, 25, ... ns: one period moves over one edge.
  sc_core::sc_start(10, sc_core::SC_NS);
  return ready;
}

PortValues ScHarness::read_ports() {
  // The order of kHarnessOutputs.
  return {cmd_ready_.read(), step_x_.read(), step_y_.read(), dir_x_.read(), dir_y_.read(), step_z_.read(),
          dir_z_.read(),     busy_.read(),   done_.read(),   err_.read(),   iter_.read()};
}

}  // namespace dda::sc
