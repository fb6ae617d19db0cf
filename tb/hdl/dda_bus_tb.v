// SPDX-License-Identifier: Apache-2.0
// Self-checking bench for a bus-level vector set written by `dda vectors --bus`
// (docs/vectors.md): the motion block (rtl/dda_motion.v, its largest queue) driven by the
// set's Wishbone cycles; with DDA_BVEC_AXIL or DDA_BVEC_SPI defined, the block behind its
// AXI4-Lite or SPI bridge (rtl/dda_motion_axil.v, rtl/dda_motion_spi.v) driven by a set of
// `dda vectors --bus --bridge axil|spi` (scripts/vector-bench.sh picks the define from the
// set's manifest). Icarus (iverilog -g2012 + vvp) and Verilator (--binary) run it
// unchanged. Argument: +vectors=DIR, the vector set.
// Each cycle: apply that cycle's inputs, clock one rising edge, compare the outputs and
// the registers of the expected word. The first mismatch prints "MISMATCH cycle N field
// F: expected E, got G" and ends the run with $fatal; a complete run prints
// "dda_bus_tb: PASS".
`timescale 1ns / 1ps
`include "dda_motion_regs.vh"
`ifdef DDA_BVEC_AXIL
`include "dda_axil_vec_fields.vh"
`elsif DDA_BVEC_SPI
`include "dda_spi_vec_fields.vh"
`else
`include "dda_bus_vec_fields.vh"
`endif

module dda_bus_tb;

  reg          clk = 1'b0;
  reg          rst_n = 1'b0;
  reg          ce = 1'b0;
  reg          estop_n = 1'b1, probe = 1'b0;
  reg  [5:0]   limit = 6'd0;
  reg  [2:0]   home = 3'd0;
  wire         step_x, step_y, dir_x, dir_y, step_z, dir_z, busy, irq;

`ifdef DDA_BVEC_AXIL
  localparam integer AW = `DDA_MOTION_ADDR_WIDTH;
  reg          awvalid = 1'b0, wvalid = 1'b0, bready = 1'b0, arvalid = 1'b0, rready = 1'b0;
  reg [AW-1:0] awaddr = '0, araddr = '0;
  reg [31:0]   wdata = 32'd0;
  reg [3:0]    wstrb = 4'hF;
  wire         awready, wready, bvalid, arready, rvalid;
  wire [1:0]   bresp, rresp;
  wire [31:0]  rdata;

  dda_motion_axil dut (
    .clk_i(clk), .rst_ni(rst_n),
    .s_awvalid_i(awvalid), .s_awready_o(awready), .s_awaddr_i(awaddr),
    .s_wvalid_i(wvalid), .s_wready_o(wready), .s_wdata_i(wdata), .s_wstrb_i(wstrb),
    .s_bvalid_o(bvalid), .s_bready_i(bready), .s_bresp_o(bresp),
    .s_arvalid_i(arvalid), .s_arready_o(arready), .s_araddr_i(araddr),
    .s_rvalid_o(rvalid), .s_rready_i(rready), .s_rdata_o(rdata), .s_rresp_o(rresp),
`elsif DDA_BVEC_SPI
  reg          csn = 1'b1, sck = 1'b0, mosi = 1'b0;
  wire         miso, miso_oe;

  dda_motion_spi dut (
    .clk_i(clk), .rst_ni(rst_n),
    .spi_csn_i(csn), .spi_sck_i(sck), .spi_mosi_i(mosi), .spi_miso_o(miso), .spi_miso_oe_o(miso_oe),
`else
  localparam integer AW = `DDA_MOTION_ADDR_WIDTH;
  reg          cyc = 1'b0, stb = 1'b0, we = 1'b0;
  reg [AW-1:0] adr = '0;
  reg [31:0]   dat_i = 32'd0;
  reg [3:0]    sel = 4'hF;
  wire [31:0]  dat_o;
  wire         ack, stall;

  dda_motion dut (
    .clk_i(clk), .rst_ni(rst_n),
    .wb_cyc_i(cyc), .wb_stb_i(stb), .wb_we_i(we), .wb_adr_i(adr), .wb_dat_i(dat_i), .wb_sel_i(sel),
    .wb_dat_o(dat_o), .wb_ack_o(ack), .wb_stall_o(stall),
`endif
    .ce_i       (ce),
    .estop_ni   (estop_n),
    .limit_i    (limit),
    .home_i     (home),
    .probe_i    (probe),
    .step_x_o   (step_x),
    .step_y_o   (step_y),
    .dir_x_o    (dir_x),
    .dir_y_o    (dir_y),
    .step_z_o   (step_z),
    .dir_z_o    (dir_z),
    .busy_o     (busy),
    .irq_o      (irq)
  );

  reg [31:0]                    counts [0:0];
  reg [`DDA_BVEC_IN_WIDTH-1:0]  vin;
  reg [`DDA_BVEC_EXP_WIDTH-1:0] vexp;
  reg [`DDA_BVEC_EXP_WIDTH-1:0] got;
  integer                       fin, fexp, cyc_n, ncycles, r1, r2;
  string                        dir;

  initial begin
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "dda_bus_tb: usage: +vectors=DIR");
    counts[0] = 0;
    $readmemh({dir, "/counts.hex"}, counts);
    ncycles = counts[0];
    if (ncycles < 1) $fatal(1, "dda_bus_tb: %s/counts.hex: no cycles", dir);
    fin = $fopen({dir, "/cycle_in.hex"}, "r");
    fexp = $fopen({dir, "/cycle_exp.hex"}, "r");
    if (fin == 0 || fexp == 0) $fatal(1, "dda_bus_tb: cannot open the cycle files in %s", dir);
    for (cyc_n = 0; cyc_n < ncycles; cyc_n = cyc_n + 1) begin
      r1 = $fscanf(fin, "%h\n", vin);
      r2 = $fscanf(fexp, "%h\n", vexp);
      if (r1 != 1 || r2 != 1) $fatal(1, "dda_bus_tb: the cycle files end before cycle %0d", cyc_n);
      `DDA_BVEC_UNPACK(vin);
      #4;
      clk = 1'b1;
      #1;
      got = `DDA_BVEC_GOT;
      if (got !== vexp) begin
        `DDA_BVEC_REPORT(cyc_n, vexp, got)
        $fatal(1, "dda_bus_tb: FAIL at cycle %0d of %0d (%s)", cyc_n, ncycles, dir);
      end
      #4;
      clk = 1'b0;
      #1;
    end
    $display("dda_bus_tb: PASS: %0d cycles, every output and register equal (%s)", ncycles, dir);
    $finish;
  end

endmodule
