// SPDX-License-Identifier: Apache-2.0
// The motion block behind an AXI4-Lite slave (rtl/dda_axil.v; docs/design.md, "Bus
// bridges"): dda_motion with the same register map, ports and parameters, the bus
// aside. Register offsets are byte addresses on the AXI bus as on Wishbone.
`include "dda_motion_regs.vh"

// The block comes with a top per bus (dda_motion and the two bridged ones): a lint of all
// of rtl/ at once sees the two bridged ones as tops, by design.
/* verilator lint_off MULTITOP */
module dda_motion_axil #(
  parameter integer DepthLog2 = `DDA_MOTION_MAX_DEPTH_LOG2,  // queue depth 2^DepthLog2 (1..7)
  parameter integer Inputs    = 1,  // the machine inputs built in (dda_motion's)
  parameter integer Axes      = 3,  // the block's axes (dda_motion's)
  parameter integer Pacer     = 1   // the pacer built in (dda_motion's)
) (
  input  wire                              clk_i,
  input  wire                              rst_ni,  // synchronous, active low
  // AXI4-Lite slave (no AWPROT/ARPROT: the block does not tell accesses apart)
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
  // iteration enable of the core (high: one iteration per clock)
  input  wire                              ce_i,
  // the machine's inputs, as on dda_motion
  input  wire                              estop_ni,
  input  wire [5:0]                        limit_i,
  input  wire [2:0]                        home_i,
  input  wire                              probe_i,
  // the axes
  output wire                              step_x_o,
  output wire                              step_y_o,
  output wire                              dir_x_o,
  output wire                              dir_y_o,
  output wire                              step_z_o,
  output wire                              dir_z_o,
  output wire                              busy_o,
  output wire                              irq_o
);

  wire                              cyc, stb, we, ack, stall, busy, irq;
  wire [`DDA_MOTION_ADDR_WIDTH-1:0] adr;
  wire [31:0]                       wdat, rdat;
  wire [3:0]                        sel;
  assign busy_o = busy;
  assign irq_o  = irq;

  dda_axil u_bridge (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .s_awvalid_i (s_awvalid_i),
    .s_awready_o (s_awready_o),
    .s_awaddr_i  (s_awaddr_i),
    .s_wvalid_i  (s_wvalid_i),
    .s_wready_o  (s_wready_o),
    .s_wdata_i   (s_wdata_i),
    .s_wstrb_i   (s_wstrb_i),
    .s_bvalid_o  (s_bvalid_o),
    .s_bready_i  (s_bready_i),
    .s_bresp_o   (s_bresp_o),
    .s_arvalid_i (s_arvalid_i),
    .s_arready_o (s_arready_o),
    .s_araddr_i  (s_araddr_i),
    .s_rvalid_o  (s_rvalid_o),
    .s_rready_i  (s_rready_i),
    .s_rdata_o   (s_rdata_o),
    .s_rresp_o   (s_rresp_o),
    .wb_cyc_o    (cyc),
    .wb_stb_o    (stb),
    .wb_we_o     (we),
    .wb_adr_o    (adr),
    .wb_dat_o    (wdat),
    .wb_sel_o    (sel),
    .wb_dat_i    (rdat),
    .wb_ack_i    (ack),
    .wb_stall_i  (stall)
  );

  dda_motion #(
    .DepthLog2 (DepthLog2),
    .Inputs    (Inputs),
    .Axes      (Axes),
    .Pacer     (Pacer)
  ) u_motion (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .wb_cyc_i   (cyc),
    .wb_stb_i   (stb),
    .wb_we_i    (we),
    .wb_adr_i   (adr),
    .wb_dat_i   (wdat),
    .wb_sel_i   (sel),
    .wb_dat_o   (rdat),
    .wb_ack_o   (ack),
    .wb_stall_o (stall),
    .ce_i       (ce_i),
    .estop_ni   (estop_ni),
    .limit_i    (limit_i),
    .home_i     (home_i),
    .probe_i    (probe_i),
    .step_x_o   (step_x_o),
    .step_y_o   (step_y_o),
    .dir_x_o    (dir_x_o),
    .dir_y_o    (dir_y_o),
    .step_z_o   (step_z_o),
    .dir_z_o    (dir_z_o),
    .busy_o     (busy),
    .irq_o      (irq)
  );

endmodule
