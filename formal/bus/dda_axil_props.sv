// SPDX-License-Identifier: Apache-2.0
// The AXI4-Lite bridge (rtl/dda_axil.v) in front of a slave that answers as the block's
// Wishbone slave does (an ack the cycle after each request taken, stall high with it),
// under any AXI4-Lite master that keeps the protocol (a VALID held, its payload stable,
// until READY) (scripts/formal-bus.sh axil). Proven: the AXI4-Lite slave's rules (a
// response held, its payload stable, until taken; OKAY); exactly one Wishbone write for
// each write address and data taken, with their address, data and lanes, and one write
// response for each; exactly one Wishbone read for each read address, one read response
// with its data for each; the bridge as a Wishbone master (stb only in a cycle, a
// request held unchanged while stalled, one at a time).
`include "dda_motion_regs.vh"

module dda_formal_axil (
  input wire                              clk_i,
  input wire                              rst_ni,
  input wire                              awvalid,
  input wire [`DDA_MOTION_ADDR_WIDTH-1:0] awaddr,
  input wire                              wvalid,
  input wire [31:0]                       wdata,
  input wire [3:0]                        wstrb,
  input wire                              bready,
  input wire                              arvalid,
  input wire [`DDA_MOTION_ADDR_WIDTH-1:0] araddr,
  input wire                              rready,
  input wire [31:0]                       s_dat    // the slave's read data, any
);
  localparam integer AW = `DDA_MOTION_ADDR_WIDTH;
  wire awready, wready, bvalid, arready, rvalid, cyc, stb, we;
  wire [1:0] bresp, rresp;
  wire [31:0] rdata, wb_wdat;
  wire [AW-1:0] adr;
  wire [3:0] sel;
  reg s_ack = 1'b0;  // the block's slave: ack_q, stall = ack_q
  reg [31:0] s_dat_q = 32'd0;

  dda_axil dut (
    .clk_i(clk_i), .rst_ni(rst_ni),
    .s_awvalid_i(awvalid), .s_awready_o(awready), .s_awaddr_i(awaddr),
    .s_wvalid_i(wvalid), .s_wready_o(wready), .s_wdata_i(wdata), .s_wstrb_i(wstrb),
    .s_bvalid_o(bvalid), .s_bready_i(bready), .s_bresp_o(bresp),
    .s_arvalid_i(arvalid), .s_arready_o(arready), .s_araddr_i(araddr),
    .s_rvalid_o(rvalid), .s_rready_i(rready), .s_rdata_o(rdata), .s_rresp_o(rresp),
    .wb_cyc_o(cyc), .wb_stb_o(stb), .wb_we_o(we), .wb_adr_o(adr), .wb_dat_o(wb_wdat), .wb_sel_o(sel),
    .wb_dat_i(s_dat_q), .wb_ack_i(s_ack), .wb_stall_i(s_ack),
    .f_awaddr_q(awaddr_q), .f_wdata_q(wdata_q), .f_wstrb_q(wstrb_q), .f_araddr_q(araddr_q)
  );
  wire [AW-1:0] awaddr_q, araddr_q;  // the bridge's buffers (renamed to outputs by the script)
  wire [31:0] wdata_q;
  wire [3:0] wstrb_q;

  wire take = cyc & stb & ~s_ack;
  always @(posedge clk_i) begin
    s_ack <= rst_ni & take;
    if (take && !we) s_dat_q <= s_dat;
  end

  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @(*) if (!f_past) assume (!rst_ni);
  // The master keeps the protocol: a VALID stays, its payload unchanged, until READY.
  always @(posedge clk_i) if (f_past && $past(rst_ni)) begin
    if ($past(awvalid && !awready)) assume (awvalid && awaddr == $past(awaddr));
    if ($past(wvalid && !wready)) assume (wvalid && wdata == $past(wdata) && wstrb == $past(wstrb));
    if ($past(arvalid && !arready)) assume (arvalid && araddr == $past(araddr));
  end

  // What the master handed over and has not had answered: the write address and data
  // taken (f_aw, f_w) and their values, the read address (f_ar); the Wishbone access
  // made for them (f_wr, f_rd: taken by the slave, not yet acked); the responses owed.
  reg f_aw = 1'b0, f_w = 1'b0, f_ar = 1'b0, f_wr = 1'b0, f_rd = 1'b0, f_b = 1'b0, f_r = 1'b0;
  reg [AW-1:0] f_awaddr, f_araddr;
  reg [31:0] f_wdata, f_rdata;
  reg [3:0] f_wstrb;
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      {f_aw, f_w, f_ar, f_wr, f_rd, f_b, f_r} <= 7'd0;
    end else begin
      if (awvalid && awready) begin f_aw <= 1'b1; f_awaddr <= awaddr; end
      if (wvalid && wready) begin f_w <= 1'b1; f_wdata <= wdata; f_wstrb <= wstrb; end
      if (arvalid && arready) begin f_ar <= 1'b1; f_araddr <= araddr; end
      if (take && we) f_wr <= 1'b1;
      if (take && !we) f_rd <= 1'b1;
      if (s_ack && f_wr) begin f_wr <= 1'b0; f_aw <= 1'b0; f_w <= 1'b0; f_b <= 1'b1; end
      if (s_ack && f_rd) begin f_rd <= 1'b0; f_ar <= 1'b0; f_r <= 1'b1; f_rdata <= s_dat_q; end
      if (bvalid && bready) f_b <= 1'b0;
      if (rvalid && rready) f_r <= 1'b0;
    end
  end

  always @(*) if (f_past && rst_ni) begin
    // Each buffer takes one address or data word at a time, and keeps it.
    assert (awready == !f_aw);
    assert (wready == !f_w);
    assert (arready == !f_ar);
    if (f_aw) assert (awaddr_q == f_awaddr);
    if (f_w) assert (wdata_q == f_wdata && wstrb_q == f_wstrb);
    if (f_ar) assert (araddr_q == f_araddr);
    // A Wishbone write only with an address and data in hand, with them; one at a time.
    if (stb && we) assert (f_aw && f_w && adr == f_awaddr && wb_wdat == f_wdata && sel == f_wstrb && !f_b);
    if (stb && !we) assert (f_ar && adr == f_araddr && !f_r);
    assert (!(f_wr && f_rd));
    if (f_wr || f_rd) assert (cyc && !stb);
    if (f_wr) assert (we);
    if (f_rd) assert (!we);
    // A response for each access made, held until taken: exactly one.
    assert (bvalid == f_b);
    assert (rvalid == f_r);
    if (rvalid) assert (rdata == f_rdata);
    assert (bresp == 2'b00 && rresp == 2'b00);
    // The bridge as a Wishbone master: stb only inside a cycle; no cycle without a
    // request owed; no second request while one is open.
    if (stb) assert (cyc);
    if (cyc) assert (stb || f_wr || f_rd);
    if (cyc && !stb) assert (f_wr || f_rd);
    if (s_ack) assert (f_wr || f_rd);
  end
  // A stalled request stays, unchanged (the block never stalls a first request: the
  // rule is checked all the same).
  always @(posedge clk_i) if (f_past && $past(rst_ni) && rst_ni && $past(stb && s_ack)) begin
    assert (stb && we == $past(we) && adr == $past(adr) && wb_wdat == $past(wb_wdat) && sel == $past(sel));
  end
endmodule
