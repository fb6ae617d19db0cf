// SPDX-License-Identifier: Apache-2.0
#include "tb/cosim/motion_cosim.hpp"

#include <verilated.h>

#include "Vdda_motion_sc.h"
#include "model/datapath/errors.hpp"
#include "tb/engines/vl_coverage.hpp"

namespace dda::motion {

BlockOutputs MotionCosim::Ports::read() const {
  BlockOutputs o;
  o.ack = ack.read();
  o.stall = stall.read();
  o.dat = dat.read();
  o.step_x = step_x.read();
  o.step_y = step_y.read();
  o.dir_x = dir_x.read();
  o.dir_y = dir_y.read();
  o.step_z = step_z.read();
  o.dir_z = dir_z.read();
  o.busy = busy.read();
  o.irq = irq.read();
  return o;
}

template <typename M>
void MotionCosim::bind(M& m, Ports& p) {
  m.clk_i(clk_);
  m.rst_ni(rst_n_);
  m.ce_i(ce_);
  m.wb_cyc_i(cyc_);
  m.wb_stb_i(stb_);
  m.wb_we_i(we_);
  m.wb_adr_i(adr_);
  m.wb_dat_i(dat_);
  m.wb_sel_i(sel_);
  m.estop_ni(estop_n_);
  m.limit_i(limit_);
  m.home_i(home_);
  m.probe_i(probe_);
  m.wb_dat_o(p.dat);
  m.wb_ack_o(p.ack);
  m.wb_stall_o(p.stall);
  m.step_x_o(p.step_x);
  m.step_y_o(p.step_y);
  m.dir_x_o(p.dir_x);
  m.dir_y_o(p.dir_y);
  m.step_z_o(p.step_z);
  m.dir_z_o(p.dir_z);
  m.busy_o(p.busy);
  m.irq_o(p.irq);
}

MotionCosim::MotionCosim() : model_(harness_build()) {
  sc_ = std::make_unique<sc::dda_motion>("sc_dut", harness_build());
  rtl_ = std::make_unique<Vdda_motion_sc>("rtl_dut");
  bind(*sc_, sc_out_);
  bind(*rtl_, rtl_out_);
  sc_core_ = std::make_unique<sc::ScSampler>(std::string(sc_->name()) + ".u_core", hw::signal_table());
  rtl_sampler_ = std::make_unique<VlBlockSampler>(*Verilated::threadContextp(),
                                                  std::string(rtl_->name()) + ".dda_motion", kHarnessDepthLog2);
  rst_n_.write(true);
  ce_.write(true);
  sel_.write(0xF);
}

MotionCosim::~MotionCosim() {
  if (rtl_) rtl_->final();
  write_coverage(*Verilated::threadContextp(), "motion_cosim");
}

std::uint64_t sc_signal_value(const std::string& name) {
  sc_core::sc_object* o = sc_core::sc_find_object(name.c_str());
  if (const auto* b = dynamic_cast<const sc_core::sc_signal<bool>*>(o)) return b->read();
  if (const auto* u = dynamic_cast<const sc_core::sc_signal<std::uint32_t>*>(o)) return u->read();
  if (const auto* l = dynamic_cast<const sc_core::sc_signal<std::uint64_t>*>(o)) return l->read();
  throw GuardError("motion cosim: the SystemC model has no register " + name);
}

BlockRegs sc_block_regs(const std::string& scope) {
  BlockRegs r{};
  for (std::size_t i = 0; i < kBlockRegs.size(); ++i)
    r[i] = sc_signal_value(scope + "." + std::string(kBlockRegs[i].name));
  return r;
}

BlockRegs MotionCosim::sc_block() const { return sc_block_regs(sc_->name()); }

void MotionCosim::tick(const BusIn& bus) {
  const BlockInputs in = block_inputs(rst_n_v_, ce_v_, bus, pins_v_);
  estop_n_.write(pins_v_.estop_n);
  limit_.write(pins_v_.limit);
  home_.write(pins_v_.home);
  probe_.write(pins_v_.probe);
  rst_n_.write(rst_n_v_);
  ce_.write(ce_v_);
  cyc_.write(bus.cyc);
  stb_.write(bus.stb);
  we_.write(bus.we);
  adr_.write(in.bus.adr);
  dat_.write(bus.dat);
  sel_.write(bus.sel);
  sc_core::sc_start(10, sc_core::SC_NS);
  model_.edge(in);
  seen_ = in.bus;
  ++cycle_;
  const std::string at = "motion cosim, cycle " + std::to_string(cycle_) + ": ";
  const BlockOutputs s = sc_out_.read(), r = rtl_out_.read();
  if (!(s == r)) throw GuardError(at + "output ports " + s.diff(r) + " (systemc/rtl)");
  if (!(s == model_.outputs())) {
    throw GuardError(at + "output ports " + s.diff(model_.outputs()) + " (systemc/reference model)");
  }
  const BlockRegs sb = sc_block(), rb = rtl_sampler_->block();
  const Signals sc_core = sc_core_->read(), rtl_core = rtl_sampler_->core();
  for (std::size_t i = 0; i < kBlockRegs.size(); ++i) {
    if (sb[i] != rb[i]) {
      throw GuardError(at + std::string(kBlockRegs[i].name) + ": " + std::to_string(sb[i]) + " vs " +
                       std::to_string(rb[i]) + " (systemc vs rtl)");
    }
  }
  for (std::size_t i = 0; i < hw::kSignals.size(); ++i) {
    if (sc_core[i] != rtl_core[i]) {
      throw GuardError(at + "u_core." + std::string(hw::kSignals[i].name) + ": " + std::to_string(sc_core[i]) + " vs " +
                       std::to_string(rtl_core[i]) + " (systemc vs rtl)");
    }
  }
  const std::string diff = compare_block(sb, sc_core, model_);
  if (!diff.empty()) throw GuardError(at + "SystemC model: " + diff);
  out_ = s;
  timing_.edge(in.bus, rst_n_v_, out_, model_.regs());
}

}  // namespace dda::motion
