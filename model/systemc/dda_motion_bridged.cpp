// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_motion_bridged.hpp"

namespace dda::sc {

namespace {
// The ports every bridged top passes to its block as they are.
template <typename Top>
void bind_motion(Top& t, dda_motion& m, BridgeWires& w) {
  m.clk_i(t.clk_i);
  m.rst_ni(t.rst_ni);
  m.ce_i(t.ce_i);
  m.estop_ni(t.estop_ni);
  m.limit_i(t.limit_i);
  m.home_i(t.home_i);
  m.probe_i(t.probe_i);
  m.step_x_o(t.step_x_o);
  m.step_y_o(t.step_y_o);
  m.dir_x_o(t.dir_x_o);
  m.dir_y_o(t.dir_y_o);
  m.step_z_o(t.step_z_o);
  m.dir_z_o(t.dir_z_o);
  m.busy_o(t.busy_o);
  m.irq_o(t.irq_o);
  m.wb_cyc_i(w.cyc);
  m.wb_stb_i(w.stb);
  m.wb_we_i(w.we);
  m.wb_adr_i(w.adr);
  m.wb_dat_i(w.wdat);
  m.wb_sel_i(w.sel);
  m.wb_dat_o(w.rdat);
  m.wb_ack_o(w.ack);
  m.wb_stall_o(w.stall);
}
template <typename B>
void bind_master(B& b, BridgeWires& w) {
  b.wb_cyc_o(w.cyc);
  b.wb_stb_o(w.stb);
  b.wb_we_o(w.we);
  b.wb_adr_o(w.adr);
  b.wb_dat_o(w.wdat);
  b.wb_sel_o(w.sel);
  b.wb_dat_i(w.rdat);
  b.wb_ack_i(w.ack);
  b.wb_stall_i(w.stall);
}
}  // namespace

dda_motion_axil::dda_motion_axil(sc_core::sc_module_name name, const motion::Build& build)
    : sc_core::sc_module(name), u_motion("u_motion", build) {
  bind_motion(*this, u_motion, w);
  bind_master(u_bridge, w);
  u_bridge.clk_i(clk_i);
  u_bridge.rst_ni(rst_ni);
  u_bridge.s_awvalid_i(s_awvalid_i);
  u_bridge.s_awaddr_i(s_awaddr_i);
  u_bridge.s_wvalid_i(s_wvalid_i);
  u_bridge.s_wdata_i(s_wdata_i);
  u_bridge.s_wstrb_i(s_wstrb_i);
  u_bridge.s_bready_i(s_bready_i);
  u_bridge.s_arvalid_i(s_arvalid_i);
  u_bridge.s_araddr_i(s_araddr_i);
  u_bridge.s_rready_i(s_rready_i);
  u_bridge.s_awready_o(s_awready_o);
  u_bridge.s_wready_o(s_wready_o);
  u_bridge.s_bvalid_o(s_bvalid_o);
  u_bridge.s_bresp_o(s_bresp_o);
  u_bridge.s_arready_o(s_arready_o);
  u_bridge.s_rvalid_o(s_rvalid_o);
  u_bridge.s_rdata_o(s_rdata_o);
  u_bridge.s_rresp_o(s_rresp_o);
}

dda_motion_spi::dda_motion_spi(sc_core::sc_module_name name, const motion::Build& build)
    : sc_core::sc_module(name), u_motion("u_motion", build) {
  bind_motion(*this, u_motion, w);
  bind_master(u_bridge, w);
  u_bridge.clk_i(clk_i);
  u_bridge.rst_ni(rst_ni);
  u_bridge.spi_csn_i(spi_csn_i);
  u_bridge.spi_sck_i(spi_sck_i);
  u_bridge.spi_mosi_i(spi_mosi_i);
  u_bridge.spi_miso_o(spi_miso_o);
  u_bridge.irq_i(irq_o);
  u_bridge.busy_i(busy_o);
  SC_METHOD(comb);
  sensitive << spi_csn_i;
}

}  // namespace dda::sc
