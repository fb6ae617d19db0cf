// SPDX-License-Identifier: Apache-2.0
#include "tb/cosim/bridge_cosim.hpp"

#include <verilated.h>

#include "Vdda_motion_axil_sc.h"
#include "Vdda_motion_spi_sc.h"
#include "model/datapath/errors.hpp"
#include "model/systemc/dda_motion_bridged.hpp"
#include "tb/cosim/motion_cosim.hpp"
#include "tb/engines/vl_coverage.hpp"

namespace dda::motion {

namespace {
using sc_core::sc_signal;

// What one model drives (names prefixed sc_ or rtl_).
struct Outs {
  explicit Outs(const std::string& p)
      : step_x((p + "step_x").c_str()),
        step_y((p + "step_y").c_str()),
        dir_x((p + "dir_x").c_str()),
        dir_y((p + "dir_y").c_str()),
        step_z((p + "step_z").c_str()),
        dir_z((p + "dir_z").c_str()),
        busy((p + "busy").c_str()),
        irq((p + "irq").c_str()),
        awready((p + "awready").c_str()),
        wready((p + "wready").c_str()),
        bvalid((p + "bvalid").c_str()),
        arready((p + "arready").c_str()),
        rvalid((p + "rvalid").c_str()),
        miso((p + "miso").c_str()),
        miso_oe((p + "miso_oe").c_str()),
        bresp((p + "bresp").c_str()),
        rdata((p + "rdata").c_str()),
        rresp((p + "rresp").c_str()) {}
  sc_signal<bool> step_x, step_y, dir_x, dir_y, step_z, dir_z, busy, irq;
  sc_signal<bool> awready, wready, bvalid, arready, rvalid, miso, miso_oe;
  sc_signal<std::uint32_t> bresp, rdata, rresp;
  BlockOutputs read(Bus bus) const {
    BlockOutputs o;
    o.step_x = step_x.read();
    o.step_y = step_y.read();
    o.dir_x = dir_x.read();
    o.dir_y = dir_y.read();
    o.step_z = step_z.read();
    o.dir_z = dir_z.read();
    o.busy = busy.read();
    o.irq = irq.read();
    if (bus == Bus::axil) {
      o.axil = {awready.read(), wready.read(), bvalid.read(), std::uint8_t(bresp.read()),
                arready.read(), rvalid.read(), rdata.read(),  std::uint8_t(rresp.read())};
    } else {
      o.spi = {miso.read(), miso_oe.read()};
    }
    return o;
  }
};
}  // namespace

struct BridgeCosim::Sim {
  sc_core::sc_clock clk{"b_clk", 10, sc_core::SC_NS, 0.5, 5, sc_core::SC_NS, true};
  sc_signal<bool> rst_n{"b_rst_n"}, ce{"b_ce"}, estop_n{"b_estop_n"}, probe{"b_probe"};
  sc_signal<std::uint32_t> limit{"b_limit"}, home{"b_home"};
  sc_signal<bool> awvalid{"b_awvalid"}, wvalid{"b_wvalid"}, bready{"b_bready"}, arvalid{"b_arvalid"},
      rready{"b_rready"}, csn{"b_csn"}, sck{"b_sck"}, mosi{"b_mosi"};
  sc_signal<std::uint32_t> awaddr{"b_awaddr"}, wdata{"b_wdata"}, wstrb{"b_wstrb"}, araddr{"b_araddr"};
  Outs sc_out{"sc_b_"}, rtl_out{"rtl_b_"};
  std::unique_ptr<sc::dda_motion_axil> sc_axil;
  std::unique_ptr<sc::dda_motion_spi> sc_spi;
  std::unique_ptr<Vdda_motion_axil_sc> rtl_axil;
  std::unique_ptr<Vdda_motion_spi_sc> rtl_spi;
  std::string sc_name;  // the SystemC top's
  std::unique_ptr<sc::ScSampler> sc_core;
  std::unique_ptr<VlBlockSampler> rtl_block;
  std::unique_ptr<VlRegSampler> rtl_bridge;

  template <typename M>
  void bind_common(M& m, Outs& o) {
    m.clk_i(clk);
    m.rst_ni(rst_n);
    m.ce_i(ce);
    m.estop_ni(estop_n);
    m.limit_i(limit);
    m.home_i(home);
    m.probe_i(probe);
    m.step_x_o(o.step_x);
    m.step_y_o(o.step_y);
    m.dir_x_o(o.dir_x);
    m.dir_y_o(o.dir_y);
    m.step_z_o(o.step_z);
    m.dir_z_o(o.dir_z);
    m.busy_o(o.busy);
    m.irq_o(o.irq);
  }
  template <typename M>
  void bind_axil(M& m, Outs& o) {
    bind_common(m, o);
    m.s_awvalid_i(awvalid);
    m.s_awaddr_i(awaddr);
    m.s_wvalid_i(wvalid);
    m.s_wdata_i(wdata);
    m.s_wstrb_i(wstrb);
    m.s_bready_i(bready);
    m.s_arvalid_i(arvalid);
    m.s_araddr_i(araddr);
    m.s_rready_i(rready);
    m.s_awready_o(o.awready);
    m.s_wready_o(o.wready);
    m.s_bvalid_o(o.bvalid);
    m.s_bresp_o(o.bresp);
    m.s_arready_o(o.arready);
    m.s_rvalid_o(o.rvalid);
    m.s_rdata_o(o.rdata);
    m.s_rresp_o(o.rresp);
  }
  template <typename M>
  void bind_spi(M& m, Outs& o) {
    bind_common(m, o);
    m.spi_csn_i(csn);
    m.spi_sck_i(sck);
    m.spi_mosi_i(mosi);
    m.spi_miso_o(o.miso);
    m.spi_miso_oe_o(o.miso_oe);
  }
  void drive(const BusIn& b) {
    awvalid.write(b.axil.awvalid);
    awaddr.write(b.axil.awaddr & ((1u << kAddrWidth) - 1));
    wvalid.write(b.axil.wvalid);
    wdata.write(b.axil.wdata);
    wstrb.write(b.axil.wstrb);
    bready.write(b.axil.bready);
    arvalid.write(b.axil.arvalid);
    araddr.write(b.axil.araddr & ((1u << kAddrWidth) - 1));
    rready.write(b.axil.rready);
    csn.write(b.spi.csn);
    sck.write(b.spi.sck);
    mosi.write(b.spi.mosi);
  }
};

BridgeCosim::BridgeCosim(Bus bus)
    : sim_(std::make_unique<Sim>()), bus_(bus), model_(harness_build()), bridge_(make_bridge(bus)) {
  Sim& s = *sim_;
  std::string rtl_top;
  if (bus == Bus::axil) {
    s.sc_axil = std::make_unique<sc::dda_motion_axil>("sc_bdut", harness_build());
    s.rtl_axil = std::make_unique<Vdda_motion_axil_sc>("rtl_bdut");
    s.bind_axil(*s.sc_axil, s.sc_out);
    s.bind_axil(*s.rtl_axil, s.rtl_out);
    rtl_top = std::string(s.rtl_axil->name()) + ".dda_motion_axil";
  } else if (bus == Bus::spi) {
    s.sc_spi = std::make_unique<sc::dda_motion_spi>("sc_bdut", harness_build());
    s.rtl_spi = std::make_unique<Vdda_motion_spi_sc>("rtl_bdut");
    s.bind_spi(*s.sc_spi, s.sc_out);
    s.bind_spi(*s.rtl_spi, s.rtl_out);
    rtl_top = std::string(s.rtl_spi->name()) + ".dda_motion_spi";
  } else {
    throw GuardError("bridge cosim: a bridge's bus, not Wishbone (MotionCosim)");
  }
  s.sc_name = "sc_bdut";
  s.sc_core = std::make_unique<sc::ScSampler>(s.sc_name + ".u_motion.u_core", hw::signal_table());
  const VerilatedContext& ctx = *Verilated::threadContextp();
  s.rtl_block = std::make_unique<VlBlockSampler>(ctx, rtl_top + ".u_motion", kHarnessDepthLog2);
  s.rtl_bridge = std::make_unique<VlRegSampler>(ctx, rtl_top + ".u_bridge", bridge_regs(bus));
  s.rst_n.write(true);
  s.ce.write(true);
  s.estop_n.write(true);
  s.csn.write(true);
}

BridgeCosim::~BridgeCosim() {
  if (sim_->rtl_axil) sim_->rtl_axil->final();
  if (sim_->rtl_spi) sim_->rtl_spi->final();
  write_coverage(*Verilated::threadContextp(), "bridge_cosim");
}

void BridgeCosim::tick(const BusIn& bus) {
  Sim& s = *sim_;
  const BlockInputs in = block_inputs(rst_n_, ce_, bridge_->wishbone(), pins_);
  const BlockOutputs before = model_.outputs();
  s.estop_n.write(pins_.estop_n);
  s.limit.write(pins_.limit);
  s.home.write(pins_.home);
  s.probe.write(pins_.probe);
  s.rst_n.write(rst_n_);
  s.ce.write(ce_);
  s.drive(bus);
  sc_core::sc_start(10, sc_core::SC_NS);
  model_.edge(in);
  bridge_->edge(rst_n_, bus, before);
  seen_ = in.bus;
  ++cycle_;
  const std::string at = "bridge cosim (" + std::string(bus_name(bus_)) + "), cycle " + std::to_string(cycle_) + ": ";
  BlockOutputs want = model_.outputs();
  bridge_->outputs(want);
  const BlockOutputs sc = s.sc_out.read(bus_), rtl = s.rtl_out.read(bus_);
  // (The block's own bus is inside the tops: its outputs are compared as registers.)
  want.ack = want.stall = false;
  want.dat = 0;
  if (!(sc == rtl)) throw GuardError(at + "output ports " + sc.diff(rtl) + " (systemc/rtl)");
  if (!(sc == want)) throw GuardError(at + "output ports " + sc.diff(want) + " (systemc/reference model)");
  const BlockRegs sb = sc_block_regs(s.sc_name + ".u_motion"), rb = s.rtl_block->block();
  const Signals scc = s.sc_core->read(), rtlc = s.rtl_block->core();
  std::string d = compare_block(rb, rtlc, model_);
  if (!d.empty()) throw GuardError(at + "RTL: " + d);
  d = compare_block(sb, scc, model_);
  if (!d.empty()) throw GuardError(at + "SystemC model: " + d);
  std::vector<std::uint64_t> scb;
  for (const auto& r : bridge_regs(bus_))
    scb.push_back(sc_signal_value(s.sc_name + ".u_bridge." + std::string(r.name)));
  d = compare_bridge(bus_, s.rtl_bridge->read(), *bridge_);
  if (!d.empty()) throw GuardError(at + "RTL: " + d);
  d = compare_bridge(bus_, scb, *bridge_);
  if (!d.empty()) throw GuardError(at + "SystemC model: " + d);
  out_ = sc;
  out_.ack = out_.stall = rb[breg("ack_q")] != 0;
  out_.dat = std::uint32_t(rb[breg("dat_q")]);
  timing_.edge(in.bus, rst_n_, out_, model_.regs());
}

}  // namespace dda::motion
