// SPDX-License-Identifier: Apache-2.0
// A bench an integrator writes from the docs alone: the motion block behind its
// AXI4-Lite bridge (rtl/dda_motion_axil.v; docs/design.md "Ports" and the register
// map, through the generated rtl/dda_motion_regs.vh), driven with the block-entry words
// `dda entries` prints (or the Python module returns). It checks ID, writes ACCEL and
// VMIN, presets the position to the first piece's start, queues every piece (its 27
// words to ENTRY + 4k, then CTRL.commit, whenever STATUS.full is low), waits for the
// queue to drain, and checks STATUS (no error), DONE_COUNT, the position registers
// against the last piece's end and the steps counted on the step/dir pins against them.
//
// +entries=FILE ($readmemh): the number of pieces, ACCEL, VMIN, then per piece its 27
// words, its start (x, y, z) and its end (x, y, z), steps as 32-bit two's complement.
`timescale 1ns / 1ns
`include "dda_motion_regs.vh"

module dda_axil_entries_tb;
  localparam integer MaxWords = 3 + 33 * 512;
  reg clk = 1'b0, rst_n = 1'b0;
  always #5 clk = ~clk;

  reg awvalid = 1'b0, wvalid = 1'b0, bready = 1'b0, arvalid = 1'b0, rready = 1'b0;
  reg [`DDA_MOTION_ADDR_WIDTH-1:0] awaddr = 0, araddr = 0;
  reg [31:0] wdata = 0;
  reg [3:0] wstrb = 4'hF;
  wire awready, wready, bvalid, arready, rvalid;
  wire [1:0] bresp, rresp;
  wire [31:0] rdata;
  wire step_x, step_y, step_z, dir_x, dir_y, dir_z, busy, irq;

  dda_motion_axil dut (
      .clk_i(clk), .rst_ni(rst_n), .ce_i(1'b1),
      .s_awvalid_i(awvalid), .s_awready_o(awready), .s_awaddr_i(awaddr),
      .s_wvalid_i(wvalid), .s_wready_o(wready), .s_wdata_i(wdata), .s_wstrb_i(wstrb),
      .s_bvalid_o(bvalid), .s_bready_i(bready), .s_bresp_o(bresp),
      .s_arvalid_i(arvalid), .s_arready_o(arready), .s_araddr_i(araddr),
      .s_rvalid_o(rvalid), .s_rready_i(rready), .s_rdata_o(rdata), .s_rresp_o(rresp),
      .estop_ni(1'b1), .limit_i(6'd0), .home_i(3'd0), .probe_i(1'b0),
      .step_x_o(step_x), .step_y_o(step_y), .step_z_o(step_z),
      .dir_x_o(dir_x), .dir_y_o(dir_y), .dir_z_o(dir_z), .busy_o(busy), .irq_o(irq));

  // The steps a drive counts: a rising step edge, in the direction the pin shows
  // (POLARITY at reset: step active high, dir high for negative).
  integer px = 0, py = 0, pz = 0;
  reg sx = 1'b0, sy = 1'b0, sz = 1'b0;
  always @(posedge clk) begin
    if (step_x && !sx) px <= px + (dir_x ? -1 : 1);
    if (step_y && !sy) py <= py + (dir_y ? -1 : 1);
    if (step_z && !sz) pz <= pz + (dir_z ? -1 : 1);
    sx <= step_x;
    sy <= step_y;
    sz <= step_z;
  end

  task fail(input [8*80-1:0] what);
    $fatal(1, "dda_axil_entries_tb: %0s", what);
  endtask

  // AXI4-Lite, one access at a time. Inputs change after a falling edge; a handshake is
  // seen right after the rising edge it happens on (the ready and valid of the cycle
  // before it).
  task axi_write(input [`DDA_MOTION_ADDR_WIDTH-1:0] a, input [31:0] d);
    reg aw_done, w_done;
    integer guard;
    begin
      @(negedge clk);
      awaddr = a;
      wdata = d;
      awvalid = 1'b1;
      wvalid = 1'b1;
      aw_done = 1'b0;
      w_done = 1'b0;
      for (guard = 0; !(aw_done && w_done); guard = guard + 1) begin
        if (guard > 64) fail("no AWREADY or WREADY");
        @(posedge clk);
        if (awvalid && awready) aw_done = 1'b1;
        if (wvalid && wready) w_done = 1'b1;
        @(negedge clk);
        if (aw_done) awvalid = 1'b0;
        if (w_done) wvalid = 1'b0;
      end
      bready = 1'b1;
      for (guard = 0; guard >= 0; guard = guard + 1) begin
        if (guard > 64) fail("no BVALID");
        @(posedge clk);
        if (bvalid) begin
          if (bresp != 2'b00) fail("BRESP not OKAY");
          guard = -2;
        end
      end
      @(negedge clk);
      bready = 1'b0;
    end
  endtask

  task axi_read(input [`DDA_MOTION_ADDR_WIDTH-1:0] a, output [31:0] d);
    integer guard;
    begin
      @(negedge clk);
      araddr = a;
      arvalid = 1'b1;
      for (guard = 0; guard >= 0; guard = guard + 1) begin
        if (guard > 64) fail("no ARREADY");
        @(posedge clk);
        if (arready) guard = -2;
      end
      @(negedge clk);
      arvalid = 1'b0;
      rready = 1'b1;
      for (guard = 0; guard >= 0; guard = guard + 1) begin
        if (guard > 64) fail("no RVALID");
        @(posedge clk);
        if (rvalid) begin
          if (rresp != 2'b00) fail("RRESP not OKAY");
          d = rdata;
          guard = -2;
        end
      end
      @(negedge clk);
      rready = 1'b0;
    end
  endtask

  reg [31:0] mem[0:MaxWords-1];
  reg [8*512-1:0] file;
  reg [31:0] v, pieces, st;
  integer k, j, base, polls;
  reg signed [31:0] want_x, want_y, want_z, got_x, got_y, got_z;

  initial begin
    if (!$value$plusargs("entries=%s", file)) fail("give +entries=FILE");
    $readmemh(file, mem);
    pieces = mem[0];
    if (pieces == 0 || 3 + 33 * pieces > MaxWords) fail("the file's piece count is 0 or too large");
    repeat (4) @(posedge clk);
    @(negedge clk);
    rst_n = 1'b1;
    axi_read(`DDA_MOTION_ID_ADDR, v);
    if (v !== `DDA_MOTION_ID_VALUE) fail("ID is not the block's");
    axi_write(`DDA_MOTION_ACCEL_ADDR, mem[1]);
    axi_write(`DDA_MOTION_VMIN_ADDR, mem[2]);
    // The position counters start at the first piece's start; the pins' count too.
    axi_write(`DDA_MOTION_POS_X_ADDR, mem[3 + 27]);
    axi_write(`DDA_MOTION_POS_Y_ADDR, mem[3 + 28]);
    axi_write(`DDA_MOTION_POS_Z_ADDR, mem[3 + 29]);
    px = $signed(mem[3 + 27]);
    py = $signed(mem[3 + 28]);
    pz = $signed(mem[3 + 29]);
    for (k = 0; k < pieces; k = k + 1) begin
      base = 3 + 33 * k;
      // Room in the queue.
      for (polls = 0; polls >= 0; polls = polls + 1) begin
        if (polls > 50000000) fail("the queue stayed full");
        axi_read(`DDA_MOTION_STATUS_ADDR, st);
        if (!st[`DDA_MOTION_STATUS_FULL_LSB]) polls = -2;
      end
      for (j = 0; j < 27; j = j + 1) axi_write(`DDA_MOTION_ENTRY_ADDR + 4 * j, mem[base + j]);
      axi_write(`DDA_MOTION_CTRL_ADDR, 32'd1 << `DDA_MOTION_CTRL_COMMIT_LSB);
    end
    // Until the queue is empty and nothing runs.
    for (polls = 0; polls >= 0; polls = polls + 1) begin
      if (polls > 50000000) fail("the queue did not drain");
      axi_read(`DDA_MOTION_STATUS_ADDR, st);
      if (st[`DDA_MOTION_STATUS_EMPTY_LSB] && !st[`DDA_MOTION_STATUS_BUSY_LSB]) polls = -2;
    end
    if (st[`DDA_MOTION_STATUS_ERR_LSB]) fail("STATUS.err is set");
    axi_read(`DDA_MOTION_DONE_COUNT_ADDR, v);
    if (v !== pieces) fail("DONE_COUNT is not the number of pieces");
    base = 3 + 33 * (pieces - 1);
    want_x = mem[base + 30];
    want_y = mem[base + 31];
    want_z = mem[base + 32];
    axi_read(`DDA_MOTION_POS_X_ADDR, got_x);
    axi_read(`DDA_MOTION_POS_Y_ADDR, got_y);
    axi_read(`DDA_MOTION_POS_Z_ADDR, got_z);
    $display("end: registers (%0d, %0d, %0d), pins (%0d, %0d, %0d), the entries' (%0d, %0d, %0d)", got_x, got_y,
             got_z, px, py, pz, want_x, want_y, want_z);
    if (got_x !== want_x || got_y !== want_y || got_z !== want_z) fail("the position registers end elsewhere");
    if (px !== want_x || py !== want_y || pz !== want_z) fail("the pins' steps end elsewhere");
    $display("PASS: %0d pieces through AXI4-Lite", pieces);
    $finish;
  end
endmodule
