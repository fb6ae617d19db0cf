// SPDX-License-Identifier: Apache-2.0
// A bus bridge on its own for place-and-route figures (scripts/bridge-synth.sh): the
// AXI4-Lite (Bus "axil", rtl/dda_axil.v) or SPI (Bus "spi", rtl/dda_spi.v) bridge in
// front of a register file in block RAM that answers as the motion block's Wishbone
// slave does (an ack the cycle after each request, stall high with it), so the bridge's
// paths end in registers as in the block. Not part of the IP.
`include "dda_motion_regs.vh"

module dda_bridge_top #(
  parameter [31:0] Bus = "axil"  // "axil" or "spi"
) (
  input  wire                              clk_i,
  input  wire                              rst_ni,
  input  wire                              s_awvalid_i,
  output wire                              s_awready_o,
  input  wire [`DDA_MOTION_ADDR_WIDTH-1:0] s_awaddr_i,
  input  wire                              s_wvalid_i,
  output wire                              s_wready_o,
  input  wire [31:0]                       s_wdata_i,
  input  wire [3:0]                        s_wstrb_i,
  output wire                              s_bvalid_o,
  input  wire                              s_bready_i,
  output wire [1:0]                        s_bresp_o,
  input  wire                              s_arvalid_i,
  output wire                              s_arready_o,
  input  wire [`DDA_MOTION_ADDR_WIDTH-1:0] s_araddr_i,
  output wire                              s_rvalid_o,
  input  wire                              s_rready_i,
  output wire [31:0]                       s_rdata_o,
  output wire [1:0]                        s_rresp_o,
  input  wire                              spi_csn_i,
  input  wire                              spi_sck_i,
  input  wire                              spi_mosi_i,
  output wire                              spi_miso_o
);
  localparam integer AW = `DDA_MOTION_ADDR_WIDTH;
  wire          cyc, stb, we;
  wire [AW-1:0] adr;
  wire [31:0]   wdat;
  wire [3:0]    sel;
  reg           ack_q = 1'b0;
  reg  [31:0]   rdat_q;
  reg  [31:0]   mem [0:(1<<(AW-2))-1];
  wire          unused_lanes = &{1'b0, adr[1:0]};  // word addresses

  always @(posedge clk_i) begin
    ack_q <= rst_ni & cyc & stb & ~ack_q;
    if (cyc && stb && !ack_q) begin
      if (we) begin
        if (sel[0]) mem[adr[AW-1:2]][7:0] <= wdat[7:0];
        if (sel[1]) mem[adr[AW-1:2]][15:8] <= wdat[15:8];
        if (sel[2]) mem[adr[AW-1:2]][23:16] <= wdat[23:16];
        if (sel[3]) mem[adr[AW-1:2]][31:24] <= wdat[31:24];
      end
      rdat_q <= mem[adr[AW-1:2]];
    end
  end

  generate
    if (Bus == "axil") begin : g_axil
      dda_axil u_bridge (
        .clk_i(clk_i), .rst_ni(rst_ni),
        .s_awvalid_i(s_awvalid_i), .s_awready_o(s_awready_o), .s_awaddr_i(s_awaddr_i),
        .s_wvalid_i(s_wvalid_i), .s_wready_o(s_wready_o), .s_wdata_i(s_wdata_i), .s_wstrb_i(s_wstrb_i),
        .s_bvalid_o(s_bvalid_o), .s_bready_i(s_bready_i), .s_bresp_o(s_bresp_o),
        .s_arvalid_i(s_arvalid_i), .s_arready_o(s_arready_o), .s_araddr_i(s_araddr_i),
        .s_rvalid_o(s_rvalid_o), .s_rready_i(s_rready_i), .s_rdata_o(s_rdata_o), .s_rresp_o(s_rresp_o),
        .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_dat_o(wdat), .wb_sel_o(sel),
        .wb_dat_i(rdat_q), .wb_ack_i(ack_q), .wb_stall_i(ack_q)
      );
      assign spi_miso_o = 1'b0;
      wire unused_spi = &{1'b0, spi_csn_i, spi_sck_i, spi_mosi_i};
    end else begin : g_spi
      dda_spi u_bridge (
        .clk_i(clk_i), .rst_ni(rst_ni),
        .spi_csn_i(spi_csn_i), .spi_sck_i(spi_sck_i), .spi_mosi_i(spi_mosi_i), .spi_miso_o(spi_miso_o),
        .irq_i(1'b0), .busy_i(1'b0),
        .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_dat_o(wdat), .wb_sel_o(sel),
        .wb_dat_i(rdat_q), .wb_ack_i(ack_q), .wb_stall_i(ack_q)
      );
      assign {s_awready_o, s_wready_o, s_bvalid_o, s_bresp_o, s_arready_o, s_rvalid_o, s_rdata_o, s_rresp_o} = '0;
      wire unused_axil = &{1'b0, s_awvalid_i, s_awaddr_i, s_wvalid_i, s_wdata_i, s_wstrb_i, s_bready_i, s_arvalid_i,
                           s_araddr_i, s_rready_i};
    end
  endgenerate
endmodule
