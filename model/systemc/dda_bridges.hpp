// SPDX-License-Identifier: Apache-2.0
// SystemC models of the bus bridges (rtl/dda_axil.v, rtl/dda_spi.v; docs/design.md, "Bus
// bridges"): same ports and registers, each a Wishbone master of the block (the block
// behind each: dda_motion_bridged.hpp).
#pragma once

#include <systemc>

#include <cstdint>

namespace dda::sc {

SC_MODULE(dda_axil) {
  sc_core::sc_in<bool> clk_i, rst_ni;
  sc_core::sc_in<bool> s_awvalid_i, s_wvalid_i, s_bready_i, s_arvalid_i, s_rready_i;
  sc_core::sc_in<std::uint32_t> s_awaddr_i, s_wdata_i, s_wstrb_i, s_araddr_i;
  sc_core::sc_out<bool> s_awready_o, s_wready_o, s_bvalid_o, s_arready_o, s_rvalid_o;
  sc_core::sc_out<std::uint32_t> s_bresp_o, s_rdata_o, s_rresp_o;
  sc_core::sc_out<bool> wb_cyc_o, wb_stb_o, wb_we_o;  // Wishbone master (to dda_motion)
  sc_core::sc_out<std::uint32_t> wb_adr_o, wb_dat_o, wb_sel_o;
  sc_core::sc_in<std::uint32_t> wb_dat_i;
  sc_core::sc_in<bool> wb_ack_i, wb_stall_i;

  SC_HAS_PROCESS(dda_axil);
  explicit dda_axil(sc_core::sc_module_name name);

  // The registers (names as in the RTL and motion::kAxilRegs).
  sc_core::sc_signal<bool> aw_q{"aw_q"}, w_q{"w_q"}, ar_q{"ar_q"}, cyc_q{"cyc_q"}, stb_q{"stb_q"}, we_q{"we_q"},
      rd_first_q{"rd_first_q"}, bvalid_q{"bvalid_q"}, rvalid_q{"rvalid_q"};
  sc_core::sc_signal<std::uint32_t> awaddr_q{"awaddr_q"}, wdata_q{"wdata_q"}, wstrb_q{"wstrb_q"}, araddr_q{"araddr_q"},
      rdata_q{"rdata_q"};

 private:
  void comb();
  void seq();
};

SC_MODULE(dda_spi) {
  sc_core::sc_in<bool> clk_i, rst_ni;
  sc_core::sc_in<bool> spi_csn_i, spi_sck_i, spi_mosi_i, irq_i, busy_i;
  sc_core::sc_out<bool> spi_miso_o;
  sc_core::sc_out<bool> wb_cyc_o, wb_stb_o, wb_we_o;  // Wishbone master (to dda_motion)
  sc_core::sc_out<std::uint32_t> wb_adr_o, wb_dat_o, wb_sel_o;
  sc_core::sc_in<std::uint32_t> wb_dat_i;
  sc_core::sc_in<bool> wb_ack_i, wb_stall_i;

  SC_HAS_PROCESS(dda_spi);
  explicit dda_spi(sc_core::sc_module_name name);

  // The registers (names as in the RTL and motion::kSpiRegs).
  sc_core::sc_signal<std::uint32_t> csn_q{"csn_q"}, sck_q{"sck_q"}, mosi_q{"mosi_q"}, cnt_q{"cnt_q"};
  sc_core::sc_signal<std::uint64_t> in_q{"in_q"}, out_q{"out_q"};
  sc_core::sc_signal<bool> miso_q{"miso_q"}, cyc_q{"cyc_q"}, stb_q{"stb_q"}, we_q{"we_q"}, done_q{"done_q"},
      bad_q{"bad_q"};
  sc_core::sc_signal<std::uint32_t> adr_q{"adr_q"}, dat_q{"dat_q"}, sel_q{"sel_q"}, rdata_q{"rdata_q"},
      count_q{"count_q"};

 private:
  void comb();
  void seq();
  void wishbone();  // the access in flight: its request taken, its ack
  void frame();     // the frame's end: an access for a whole one
};

}  // namespace dda::sc
