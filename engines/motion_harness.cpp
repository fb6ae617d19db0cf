// SPDX-License-Identifier: Apache-2.0
#include "motion_harness.hpp"

#include <verilated.h>
#include <verilated_syms.h>

#include "Vdda_motion.h"
#include "datapath/errors.hpp"
#include "vl_sampler.hpp"
#include "vl_waveform.hpp"

namespace dda::motion {

namespace {

const char* kTop = "dut.dda_motion";

std::uint64_t read_var(const void* p, int bytes) {
  switch (bytes) {
    case 1:
      return *static_cast<const std::uint8_t*>(p);
    case 2:
      return *static_cast<const std::uint16_t*>(p);
    case 4:
      return *static_cast<const std::uint32_t*>(p);
    default:
      return *static_cast<const std::uint64_t*>(p);
  }
}

}  // namespace

static int bytes_of(const VerilatedVar& v) {
  return v.vltype() == VLVT_UINT8 ? 1 : v.vltype() == VLVT_UINT16 ? 2 : v.vltype() == VLVT_UINT32 ? 4 : 8;
}

VlBlockSampler::VlBlockSampler(const VerilatedContext& ctx, const std::string& scope, int depth_log2) {
  const VerilatedScope* s = ctx.scopeFind(scope.c_str());
  if (!s) throw GuardError("motion sampler: no scope " + scope);
  for (const auto& r : kBlockRegs) {
    // "u_sx.step_q", "u_io.u_estop.s1_q": a register of a submodule, in its scope.
    const std::size_t dot = r.name.rfind('.');
    const VerilatedScope* rs = s;
    if (dot != std::string_view::npos) {
      const std::string sub = scope + "." + std::string(r.name.substr(0, dot));
      rs = ctx.scopeFind(sub.c_str());
      if (!rs) throw GuardError("motion sampler: no scope " + sub);
    }
    const std::string var(dot == std::string_view::npos ? r.name : r.name.substr(dot + 1));
    VerilatedVar* v = rs->varFind(var.c_str());
    if (!v) throw GuardError("motion sampler: the RTL has no public register " + std::string(r.name));
    const int width = v->dims() == 0 ? 1 : v->packed().elements();
    if (width != width_bits(r.width, depth_log2)) {
      throw GuardError("motion sampler: the RTL's " + std::string(r.name) + " is " + std::to_string(width) +
                       " bits wide, the model says " + std::to_string(width_bits(r.width, depth_log2)));
    }
    block_.push_back(Var{v->datap(), bytes_of(*v), width});
  }
  // The core's register table, read below the block's instance by the core's sampler.
  core_ = std::make_unique<rtl::VlSampler>(ctx, scope + ".u_core", hw::signal_table());
}

BlockRegs VlBlockSampler::block() const {
  BlockRegs r{};
  for (std::size_t i = 0; i < block_.size(); ++i) {
    const auto& v = block_[i];
    r[i] = read_var(v.p, v.bytes) & ((v.width >= 64 ? 0 : std::uint64_t{1} << v.width) - 1);
  }
  return r;
}

Signals VlBlockSampler::core() const { return core_->read(); }

std::string compare_block(const BlockRegs& got, const Signals& got_core, const MotionModel& m) {
  for (std::size_t i = 0; i < kBlockRegs.size(); ++i) {
    if (got[i] != m.regs()[i]) {
      return std::string(kBlockRegs[i].name) + " is " + std::to_string(got[i]) + ", the reference model says " +
             std::to_string(m.regs()[i]);
    }
  }
  for (std::size_t i = 0; i < hw::kSignals.size(); ++i) {
    if (got_core[i] != m.core()[i]) {
      return "u_core." + std::string(hw::kSignals[i].name) + " is " + std::to_string(got_core[i]) +
             ", the reference model says " + std::to_string(m.core()[i]);
    }
  }
  return "";
}

MotionHarness::MotionHarness(const std::string& vcd)
    : ctx_(std::make_unique<VerilatedContext>()), model_(kHarnessDepthLog2) {
  ctx_->traceEverOn(!vcd.empty());
  // Verilator (5.006) files a model's scopes under the thread's current context when
  // the model is built and looks them up there again when it is destroyed: make it this
  // harness' context both times, so that two harnesses can live side by side.
  Verilated::threadContextp(ctx_.get());
  top_ = std::make_unique<Vdda_motion>(ctx_.get(), "dut");
  top_->clk_i = 0;
  top_->rst_ni = 0;
  top_->ce_i = 0;
  top_->estop_ni = 1;
  top_->wb_cyc_i = top_->wb_stb_i = top_->wb_we_i = 0;
  top_->eval();
  sampler_ = std::make_unique<VlBlockSampler>(*ctx_, kTop, kHarnessDepthLog2);
  vcd_ = open_waveform(*top_, *ctx_, vcd);
}

MotionHarness::~MotionHarness() {
  if (vcd_) vcd_->close();
  if (top_) top_->final();
  Verilated::threadContextp(ctx_.get());  // (see the constructor)
  top_.reset();
}

void MotionHarness::tick(const BusIn& bus) {
  const BlockInputs in = block_inputs(rst_n_, ce_, bus, pins_);
  top_->rst_ni = rst_n_;
  top_->ce_i = ce_;
  top_->estop_ni = pins_.estop_n;
  top_->limit_i = pins_.limit;
  top_->home_i = pins_.home;
  top_->probe_i = pins_.probe;
  top_->wb_cyc_i = bus.cyc;
  top_->wb_stb_i = bus.stb;
  top_->wb_we_i = bus.we;
  top_->wb_adr_i = in.bus.adr;
  top_->wb_dat_i = bus.dat;
  top_->wb_sel_i = bus.sel;
  half_period(*top_, *ctx_, vcd_.get(), false);
  half_period(*top_, *ctx_, vcd_.get(), true);
  model_.edge(in);
  ++cycle_;

  out_.ack = top_->wb_ack_o;
  out_.stall = top_->wb_stall_o;
  out_.dat = top_->wb_dat_o;
  out_.step_x = top_->step_x_o;
  out_.step_y = top_->step_y_o;
  out_.dir_x = top_->dir_x_o;
  out_.dir_y = top_->dir_y_o;
  out_.step_z = top_->step_z_o;
  out_.dir_z = top_->dir_z_o;
  out_.busy = top_->busy_o;
  out_.irq = top_->irq_o;
  const std::string at = "motion block, cycle " + std::to_string(cycle_) + ": ";
  const BlockOutputs want = model_.outputs();
  if (!(out_ == want)) throw GuardError(at + "output ports " + out_.diff(want) + " (rtl/reference model)");
  const std::string diff = compare_block(sampler_->block(), sampler_->core(), model_);
  if (!diff.empty()) throw GuardError(at + diff);
  timing_.edge(in.bus, rst_n_, out_, model_.regs());
}

}  // namespace dda::motion
