// SPDX-License-Identifier: Apache-2.0
// AXI4-Lite slave in front of the motion block's Wishbone slave (docs/design.md, "Bus
// bridges"): a thin wrapper with no registers of its own in the map, one access at a time.
// Each address channel and the write data channel have a one-entry buffer: AWREADY,
// WREADY and ARREADY are high while theirs is empty. Once a write's address and data are
// both in (in either order, or together) and no write response waits, the bridge makes
// one Wishbone write with WSTRB as the byte lanes; once a read address is in and no read
// data waits, one read. The write response (BRESP OKAY) and the read data (RRESP OKAY)
// stay valid until taken. A read and a write both ready take turns. The block answers
// every request (errors are its sticky status bits), so the responses are always OKAY.
// Every output is a register or a function of registers only: no path from an input to
// an output.
`include "dda_motion_regs.vh"

module dda_axil (
  input  wire                              clk_i,
  input  wire                              rst_ni,  // synchronous, active low
  // AXI4-Lite slave
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
  // Wishbone B4 pipelined master (to dda_motion)
  output wire                              wb_cyc_o,
  output wire                              wb_stb_o,
  output wire                              wb_we_o,
  output wire [`DDA_MOTION_ADDR_WIDTH-1:0] wb_adr_o,
  output wire [31:0]                       wb_dat_o,
  output wire [3:0]                        wb_sel_o,
  input  wire [31:0]                       wb_dat_i,
  input  wire                              wb_ack_i,
  input  wire                              wb_stall_i
);

  localparam integer AW = `DDA_MOTION_ADDR_WIDTH;

  reg          aw_q /* verilator public_flat_rd */;  // a write address waits
  reg [AW-1:0] awaddr_q /* verilator public_flat_rd */;
  reg          w_q /* verilator public_flat_rd */;  // write data wait
  reg [31:0]   wdata_q /* verilator public_flat_rd */;
  reg [3:0]    wstrb_q /* verilator public_flat_rd */;
  reg          ar_q /* verilator public_flat_rd */;  // a read address waits
  reg [AW-1:0] araddr_q /* verilator public_flat_rd */;
  reg          cyc_q /* verilator public_flat_rd */;  // a Wishbone cycle is open
  reg          stb_q /* verilator public_flat_rd */;  // its request is not taken yet
  reg          we_q /* verilator public_flat_rd */;
  reg          rd_first_q /* verilator public_flat_rd */;  // the read's turn when both wait
  reg          bvalid_q /* verilator public_flat_rd */;
  reg          rvalid_q /* verilator public_flat_rd */;
  reg [31:0]   rdata_q /* verilator public_flat_rd */;

  assign s_awready_o = ~aw_q;
  assign s_wready_o  = ~w_q;
  assign s_arready_o = ~ar_q;
  assign s_bvalid_o  = bvalid_q;
  assign s_bresp_o   = 2'b00;
  assign s_rvalid_o  = rvalid_q;
  assign s_rdata_o   = rdata_q;
  assign s_rresp_o   = 2'b00;
  assign wb_cyc_o    = cyc_q;
  assign wb_stb_o    = stb_q;
  assign wb_we_o     = we_q;
  assign wb_adr_o    = we_q ? awaddr_q : araddr_q;
  assign wb_dat_o    = wdata_q;
  assign wb_sel_o    = wstrb_q;

  wire can_wr = aw_q & w_q & ~bvalid_q;
  wire can_rd = ar_q & ~rvalid_q;
  wire go_rd  = can_rd & (rd_first_q | ~can_wr);

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      aw_q       <= 1'b0;
      awaddr_q   <= '0;
      w_q        <= 1'b0;
      wdata_q    <= 32'd0;
      wstrb_q    <= 4'd0;
      ar_q       <= 1'b0;
      araddr_q   <= '0;
      cyc_q      <= 1'b0;
      stb_q      <= 1'b0;
      we_q       <= 1'b0;
      rd_first_q <= 1'b0;
      bvalid_q   <= 1'b0;
      rvalid_q   <= 1'b0;
      rdata_q    <= 32'd0;
    end else begin
      if (s_awvalid_i && !aw_q) begin
        aw_q     <= 1'b1;
        awaddr_q <= s_awaddr_i;
      end
      if (s_wvalid_i && !w_q) begin
        w_q     <= 1'b1;
        wdata_q <= s_wdata_i;
        wstrb_q <= s_wstrb_i;
      end
      if (s_arvalid_i && !ar_q) begin
        ar_q     <= 1'b1;
        araddr_q <= s_araddr_i;
      end
      if (s_bready_i) bvalid_q <= 1'b0;
      if (s_rready_i) rvalid_q <= 1'b0;
      if (!cyc_q) begin
        if (can_wr || can_rd) begin
          cyc_q      <= 1'b1;
          stb_q      <= 1'b1;
          we_q       <= ~go_rd;
          rd_first_q <= ~go_rd;
        end
      end else begin
        if (!wb_stall_i) stb_q <= 1'b0;
        if (wb_ack_i && !stb_q) begin
          cyc_q <= 1'b0;
          if (we_q) begin
            aw_q     <= 1'b0;
            w_q      <= 1'b0;
            bvalid_q <= 1'b1;
          end else begin
            ar_q     <= 1'b0;
            rvalid_q <= 1'b1;
            rdata_q  <= wb_dat_i;
          end
        end
      end
    end
  end

endmodule
