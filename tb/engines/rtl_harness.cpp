// SPDX-License-Identifier: Apache-2.0
#include "tb/engines/rtl_harness.hpp"

#include <verilated.h>

#include "Vdda_core.h"
#include "model/datapath/hw_command.hpp"
#include "tb/engines/vl_coverage.hpp"
#include "tb/engines/vl_waveform.hpp"

namespace dda::rtl {

RtlHarness::RtlHarness(const std::string& vcd) : ctx_(std::make_unique<VerilatedContext>()) {
  ctx_->traceEverOn(!vcd.empty());
  // Verilator (5.006) files a model's scopes under the thread's current context when
  // the model is built and looks them up there again when it is destroyed: make it this
  // harness' context both times, so that two harnesses can live side by side.
  Verilated::threadContextp(ctx_.get());
  top_ = std::make_unique<Vdda_core>(ctx_.get(), "dut");
  top_->clk_i = 0;
  top_->rst_ni = 0;
  top_->ce_i = 0;
  top_->cmd_valid_i = 0;
  top_->eval();
  sampler_ = std::make_unique<VlSampler>(*ctx_, "dut.dda_core", hw::signal_table());
  vcd_ = open_waveform(*top_, *ctx_, vcd);
}

RtlHarness::~RtlHarness() {
  close_trace();
  if (top_) top_->final();
  write_coverage(*ctx_, "rtl");
  Verilated::threadContextp(ctx_.get());  // (see the constructor)
  top_.reset();
}

void RtlHarness::close_trace() {
  if (vcd_) {
    vcd_->close();
    vcd_.reset();
  }
}

void RtlHarness::resolve(const hw::SignalTable& t) const { VlSampler(*ctx_, "dut.dda_core", t); }

void RtlHarness::apply(const CoreInputs& in, bool cmd_changed) {
  top_->rst_ni = in.rst_n;
  top_->ce_i = in.ce;
  top_->cmd_valid_i = in.cmd_valid;
  if (!cmd_changed) return;
  const auto words = hw::pack_fields(in.cmd);
  for (std::size_t i = 0; i < words.size(); ++i) top_->cmd_i[i] = words[i];
}

bool RtlHarness::cmd_ready() {
  top_->eval();
  return top_->cmd_ready_o;
}

bool RtlHarness::edge() {
  // Inputs were set while the clock is low; a 10-unit period, rising edge in the middle.
  half_period(*top_, *ctx_, vcd_.get(), false);
  const bool ready = top_->cmd_ready_o;  // (the outputs before the edge)
  half_period(*top_, *ctx_, vcd_.get(), true);
  return ready;
}

PortValues RtlHarness::read_ports() {
  // The order of kHarnessOutputs.
  return {top_->cmd_ready_o, top_->step_x_o, top_->step_y_o, top_->dir_x_o, top_->dir_y_o, top_->step_z_o,
          top_->dir_z_o,     top_->busy_o,   top_->done_o,   top_->err_o,   top_->iter_o};
}

}  // namespace dda::rtl
