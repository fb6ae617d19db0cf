// SPDX-License-Identifier: Apache-2.0
#include "motion_harness.hpp"

#include <verilated.h>
#include <verilated_syms.h>
#include <verilated_vcd_c.h>

#include "Vdda_motion.h"
#include "dda/errors.hpp"
#include "vl_sampler.hpp"

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

MotionHarness::MotionHarness(const std::string& vcd)
    : ctx_(std::make_unique<VerilatedContext>()), model_(kHarnessDepthLog2) {
  ctx_->traceEverOn(!vcd.empty());
  top_ = std::make_unique<Vdda_motion>(ctx_.get(), "dut");
  top_->clk_i = 0;
  top_->rst_ni = 0;
  top_->ce_i = 0;
  top_->wb_cyc_i = top_->wb_stb_i = top_->wb_we_i = 0;
  top_->eval();
  const VerilatedScope* s = ctx_->scopeFind(kTop);
  if (!s) throw GuardError(std::string("motion harness: no scope ") + kTop);
  for (const auto& r : kBlockRegs) {
    VerilatedVar* v = s->varFind(std::string(r.name).c_str());
    if (!v) throw GuardError("motion harness: the RTL has no public register " + std::string(r.name));
    const int width = v->dims() == 0 ? 1 : v->packed().elements();
    if (width != width_bits(r.width, kHarnessDepthLog2)) {
      throw GuardError("motion harness: the RTL's " + std::string(r.name) + " is " + std::to_string(width) +
                       " bits wide, the model says " + std::to_string(width_bits(r.width, kHarnessDepthLog2)));
    }
    const int bytes = v->vltype() == VLVT_UINT8    ? 1
                      : v->vltype() == VLVT_UINT16 ? 2
                      : v->vltype() == VLVT_UINT32 ? 4
                                                   : 8;
    block_vars_.push_back(Var{std::string(r.name), v->datap(), bytes, width});
  }
  // The core's register table, read below the block's instance (the same sampler as
  // the core's own harness).
  const std::string core_scope = std::string(kTop) + ".u_core";
  for (const auto& r : hw::kSignals) {
    const std::string name(r.name);
    const auto dot = name.rfind('.');
    const std::string scope = dot == std::string::npos ? core_scope : core_scope + "." + name.substr(0, dot);
    const std::string var = dot == std::string::npos ? name : name.substr(dot + 1);
    const VerilatedScope* cs = ctx_->scopeFind(scope.c_str());
    VerilatedVar* v = cs ? cs->varFind(var.c_str()) : nullptr;
    if (!v) throw GuardError("motion harness: the RTL has no public signal " + name + " in " + core_scope);
    const int bytes = v->vltype() == VLVT_UINT8    ? 1
                      : v->vltype() == VLVT_UINT16 ? 2
                      : v->vltype() == VLVT_UINT32 ? 4
                                                   : 8;
    core_vars_.push_back(Var{name, v->datap(), bytes, r.width});
  }
  if (!vcd.empty()) {
    vcd_ = std::make_unique<VerilatedVcdC>();
    top_->trace(vcd_.get(), 99);
    vcd_->open(vcd.c_str());
    if (!vcd_->isOpen()) throw GuardError("cannot write the waveform '" + vcd + "'");
    vcd_->dump(ctx_->time());
  }
}

MotionHarness::~MotionHarness() {
  if (vcd_) vcd_->close();
  if (top_) top_->final();
}

void MotionHarness::tick(const BusIn& bus) {
  top_->rst_ni = rst_n_;
  top_->ce_i = ce_;
  top_->wb_cyc_i = bus.cyc;
  top_->wb_stb_i = bus.stb;
  top_->wb_we_i = bus.we;
  top_->wb_adr_i = bus.adr & ((1u << kAddrWidth) - 1);
  top_->wb_dat_i = bus.dat;
  top_->wb_sel_i = bus.sel;
  top_->clk_i = 0;
  top_->eval();
  ctx_->timeInc(5);
  if (vcd_) vcd_->dump(ctx_->time());
  top_->clk_i = 1;
  top_->eval();
  ctx_->timeInc(5);
  if (vcd_) vcd_->dump(ctx_->time());
  BlockInputs in;
  in.rst_n = rst_n_;
  in.ce = ce_;
  in.bus = bus;
  in.bus.adr &= (1u << kAddrWidth) - 1;
  model_.edge(in);
  ++cycle_;

  out_.ack = top_->wb_ack_o;
  out_.stall = top_->wb_stall_o;
  out_.dat = top_->wb_dat_o;
  out_.step_x = top_->step_x_o;
  out_.step_y = top_->step_y_o;
  out_.dir_x = top_->dir_x_o;
  out_.dir_y = top_->dir_y_o;
  out_.busy = top_->busy_o;
  out_.irq = top_->irq_o;
  const std::string at = "motion block, cycle " + std::to_string(cycle_) + ": ";
  const BlockOutputs want = model_.outputs();
  if (!(out_ == want)) {
    throw GuardError(at + "ports differ from the reference model (ack " + std::to_string(out_.ack) + "/" +
                     std::to_string(want.ack) + ", dat " + std::to_string(out_.dat) + "/" + std::to_string(want.dat) +
                     ", step " + std::to_string(out_.step_x) + std::to_string(out_.step_y) + "/" +
                     std::to_string(want.step_x) + std::to_string(want.step_y) + ", irq " + std::to_string(out_.irq) +
                     "/" + std::to_string(want.irq) + ")");
  }
  for (std::size_t i = 0; i < block_vars_.size(); ++i) {
    const auto& v = block_vars_[i];
    const std::uint64_t got = read_var(v.p, v.bytes) & ((v.width >= 64 ? 0 : std::uint64_t{1} << v.width) - 1);
    if (got != model_.regs()[i]) {
      throw GuardError(at + v.name + " is " + std::to_string(got) + ", the reference model says " +
                       std::to_string(model_.regs()[i]));
    }
  }
  const Signals& core = model_.core();
  for (std::size_t i = 0; i < core_vars_.size(); ++i) {
    const auto& v = core_vars_[i];
    const std::uint64_t mask = v.width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << v.width) - 1;
    const std::uint64_t got = read_var(v.p, v.bytes) & mask;
    if (got != core[i]) {
      throw GuardError(at + "u_core." + v.name + " is " + std::to_string(got) + ", the reference model says " +
                       std::to_string(core[i]));
    }
  }
}

}  // namespace dda::motion
