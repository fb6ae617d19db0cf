// SPDX-License-Identifier: Apache-2.0
// SystemC models of the block behind its bridges (rtl/dda_motion_axil.v,
// rtl/dda_motion_spi.v): the same ports and hierarchy, u_bridge (dda_bridges.hpp) in
// front of u_motion (dda_motion.hpp).
#pragma once

#include <systemc>

#include <cstdint>

#include "model/systemc/dda_bridges.hpp"
#include "model/systemc/dda_motion.hpp"

namespace dda::sc {

// The wires between a bridge and the block inside a bridged top.
struct BridgeWires {
  sc_core::sc_signal<bool> cyc{"cyc"}, stb{"stb"}, we{"we"}, ack{"ack"}, stall{"stall"};
  sc_core::sc_signal<std::uint32_t> adr{"adr"}, wdat{"wdat"}, sel{"sel"}, rdat{"rdat"};
};

// rtl/dda_motion_axil.v
SC_MODULE(dda_motion_axil) {
  sc_core::sc_in<bool> clk_i, rst_ni, ce_i, estop_ni, probe_i;  // as dda_motion's
  sc_core::sc_in<std::uint32_t> limit_i, home_i;
  sc_core::sc_out<bool> step_x_o, step_y_o, dir_x_o, dir_y_o, step_z_o, dir_z_o, busy_o, irq_o;
  sc_core::sc_in<bool> s_awvalid_i, s_wvalid_i, s_bready_i, s_arvalid_i, s_rready_i;
  sc_core::sc_in<std::uint32_t> s_awaddr_i, s_wdata_i, s_wstrb_i, s_araddr_i;
  sc_core::sc_out<bool> s_awready_o, s_wready_o, s_bvalid_o, s_arready_o, s_rvalid_o;
  sc_core::sc_out<std::uint32_t> s_bresp_o, s_rdata_o, s_rresp_o;

  dda_motion_axil(sc_core::sc_module_name name, const motion::Build& build);
  dda_axil u_bridge{"u_bridge"};
  dda_motion u_motion;
  BridgeWires w;
};

// rtl/dda_motion_spi.v (spi_miso_oe_o = ~spi_csn_i)
SC_MODULE(dda_motion_spi) {
  sc_core::sc_in<bool> clk_i, rst_ni, ce_i, estop_ni, probe_i;  // as dda_motion's
  sc_core::sc_in<std::uint32_t> limit_i, home_i;
  sc_core::sc_out<bool> step_x_o, step_y_o, dir_x_o, dir_y_o, step_z_o, dir_z_o, busy_o, irq_o;
  sc_core::sc_in<bool> spi_csn_i, spi_sck_i, spi_mosi_i;
  sc_core::sc_out<bool> spi_miso_o, spi_miso_oe_o;

  SC_HAS_PROCESS(dda_motion_spi);
  dda_motion_spi(sc_core::sc_module_name name, const motion::Build& build);
  dda_spi u_bridge{"u_bridge"};
  dda_motion u_motion;
  BridgeWires w;

 private:
  void comb() { spi_miso_oe_o.write(!spi_csn_i.read()); }
};

}  // namespace dda::sc
