// SPDX-License-Identifier: Apache-2.0
// The SPI bridge (rtl/dda_spi.v) in front of a slave that answers as the block's
// Wishbone slave does, under any SCK, CS_n and MOSI (scripts/formal-bus.sh spi).
// Proven: the pins reach the bridge through two flip-flops; a frame as the bridge sees
// it (CS_n low, counting SCK's rising edges) makes exactly one Wishbone access when it
// ends after exactly the frame's edges, with the command, address and data its MOSI
// bits carried, and none when it ends after fewer or more; the access is made, and
// acked, before the next frame can end; the bridge as a Wishbone master keeps the rules.
`include "dda_motion_regs.vh"

module dda_formal_spi (
  input wire        clk_i,
  input wire        rst_ni,
  input wire        csn,
  input wire        sck,
  input wire        mosi,
  input wire        irq,
  input wire        busy,
  input wire [31:0] s_dat
);
  localparam integer AW = `DDA_MOTION_ADDR_WIDTH;
  localparam integer Bits = `DDA_MOTION_SPI_FRAME_BITS;
  localparam integer In = `DDA_MOTION_SPI_DATA_AT + `DDA_MOTION_SPI_DATA_WIDTH;
  wire miso, cyc, stb, we;
  wire [AW-1:0] adr;
  wire [31:0] wdat;
  wire [3:0] sel;
  reg s_ack = 1'b0;
  reg [31:0] s_dat_q = 32'd0;

  dda_spi dut (
    .clk_i(clk_i), .rst_ni(rst_ni), .spi_csn_i(csn), .spi_sck_i(sck), .spi_mosi_i(mosi),
    .spi_miso_o(miso), .irq_i(irq), .busy_i(busy),
    .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_dat_o(wdat), .wb_sel_o(sel),
    .wb_dat_i(s_dat_q), .wb_ack_i(s_ack), .wb_stall_i(s_ack),
    .f_csn_q(csn_q), .f_sck_q(sck_q), .f_mosi_q(mosi_q), .f_cnt_q(cnt_q), .f_in_q(in_q)
  );
  wire [2:0] csn_q, sck_q;  // the bridge's registers (renamed to outputs by the script)
  wire [1:0] mosi_q;
  wire [6:0] cnt_q;
  wire [In-1:0] in_q;

  wire take = cyc & stb & ~s_ack;
  always @(posedge clk_i) begin
    s_ack <= rst_ni & take;
    if (take && !we) s_dat_q <= s_dat;
  end

  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @(*) if (!f_past) assume (!rst_ni);

  // The pins two clocks ago (after reset: the idle levels), as the bridge must see them.
  reg [1:0] f_csn = 2'b11, f_sck = 2'b00, f_mosi = 2'b00;
  always @(posedge clk_i) begin
    f_csn  <= rst_ni ? {f_csn[0], csn} : 2'b11;
    f_sck  <= rst_ni ? {f_sck[0], sck} : 2'b00;
    f_mosi <= rst_ni ? {f_mosi[0], mosi} : 2'b00;
  end
  // The frame as the bridge sees it: CS_n (delayed) low, the rising edges of SCK
  // (delayed) counted up to one over the frame's, the MOSI bits that came with them.
  reg f_csn_d = 1'b1, f_sck_d = 1'b0;  // the delayed pins one clock before
  reg [6:0] f_edges = 7'd0;
  reg [In-1:0] f_bits;
  reg f_owed = 1'b0;  // a whole frame ended: its access not taken yet
  reg [In-1:0] f_frame;  // that frame's bits
  wire f_rise = !f_csn[1] && f_sck[1] && !f_sck_d;
  wire f_end  = !f_csn_d && f_csn[1];
  always @(posedge clk_i) begin
    f_csn_d <= rst_ni ? f_csn[1] : 1'b1;
    f_sck_d <= rst_ni ? f_sck[1] : 1'b0;
    if (!rst_ni) begin
      f_edges <= 7'd0;
      f_bits  <= '0;
      f_owed  <= 1'b0;
    end else begin
      if (f_csn_d && !f_csn[1]) f_edges <= 7'd0;
      else if (f_rise && f_edges <= 7'(Bits)) begin
        f_edges <= f_edges + 7'd1;
        if (f_edges < 7'(In)) f_bits <= {f_bits[In-2:0], f_mosi[1]};
      end
      if (take) f_owed <= 1'b0;
      if (f_end && f_edges == 7'(Bits)) begin
        f_owed  <= 1'b1;
        f_frame <= f_bits;
      end
    end
  end

  localparam integer CmdLo = In - `DDA_MOTION_SPI_COMMAND_AT - `DDA_MOTION_SPI_COMMAND_WIDTH;
  localparam integer AdrLo = In - `DDA_MOTION_SPI_ADDRESS_AT - `DDA_MOTION_SPI_ADDRESS_WIDTH;
  always @(*) if (f_past && rst_ni) begin
    // The synchronizers: the pins two clocks late.
    assert (csn_q == {f_csn_d, f_csn} && sck_q == {f_sck_d, f_sck} && mosi_q == f_mosi);
    // The bridge counts the frame's edges and keeps its bits as they came.
    assert (cnt_q == f_edges);
    assert (in_q == f_bits);
    // An access only for a whole frame, with its bits; one at a time.
    if (stb) assert (f_owed && cyc);
    if (f_owed) assert (stb && cyc);
    if (stb) begin
      assert (we == f_frame[CmdLo + `DDA_MOTION_SPI_WRITE_BIT]);
      assert (sel == f_frame[CmdLo+:4]);
      assert (adr == f_frame[AdrLo+:AW]);
      assert (wdat == f_frame[31:0]);
    end
    if (cyc && !stb) assert (!f_owed);
    if (s_ack) assert (cyc && !stb);
    if (cyc) assert (stb != s_ack);  // the request, then its ack: two clocks
    // The access ends before another frame can: it takes two clocks, a frame's edges
    // two clocks each at the least.
    if (cyc) assert (f_edges <= 7'd1 || f_edges == 7'(Bits));
  end
endmodule
