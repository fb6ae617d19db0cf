// SPDX-License-Identifier: Apache-2.0
// The motion block's Wishbone B4 slave (rtl/dda_motion.v, the queue at its smallest),
// its bus rules under any master, classic or pipelined (scripts/formal-bus.sh wb):
// exactly one ack for each request taken (cyc & stb while stall is low), one cycle after
// it, and none without one; stall high in the ack cycle, so a classic master that holds
// stb through it is not taken twice; the read data with the ack. The block's logic
// behind the bus is read too, its own assertions set aside (the core's proofs own them).
`include "dda_motion_regs.vh"

module dda_formal_wb (
  input wire                              clk_i,
  input wire                              rst_ni,
  input wire                              wb_cyc_i,
  input wire                              wb_stb_i,
  input wire                              wb_we_i,
  input wire [`DDA_MOTION_ADDR_WIDTH-1:0] wb_adr_i,
  input wire [31:0]                       wb_dat_i,
  input wire [3:0]                        wb_sel_i,
  input wire                              ce_i,
  input wire                              estop_ni,
  input wire [5:0]                        limit_i,
  input wire [2:0]                        home_i,
  input wire                              probe_i
);
  wire [31:0] dat;
  wire ack, stall, step_x, step_y, dir_x, dir_y, step_z, dir_z, busy, irq;

  dda_motion #(.DepthLog2(1)) dut (
    .clk_i(clk_i), .rst_ni(rst_ni), .wb_cyc_i(wb_cyc_i), .wb_stb_i(wb_stb_i), .wb_we_i(wb_we_i),
    .wb_adr_i(wb_adr_i), .wb_dat_i(wb_dat_i), .wb_sel_i(wb_sel_i), .wb_dat_o(dat), .wb_ack_o(ack),
    .wb_stall_o(stall), .ce_i(ce_i), .estop_ni(estop_ni), .limit_i(limit_i), .home_i(home_i),
    .probe_i(probe_i), .step_x_o(step_x), .step_y_o(step_y), .dir_x_o(dir_x), .dir_y_o(dir_y),
    .step_z_o(step_z), .dir_z_o(dir_z), .busy_o(busy), .irq_o(irq)
  );

  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @(*) if (!f_past) assume (!rst_ni);
  // B4: a master raises stb only inside a cycle.
  always @(*) assume (!wb_stb_i || wb_cyc_i);

  wire f_req = wb_cyc_i & wb_stb_i & ~stall;  // a request the slave takes
  reg  f_req_q = 1'b0, f_rd_q = 1'b0;
  always @(posedge clk_i) begin
    f_req_q <= rst_ni & f_req;
    f_rd_q  <= rst_ni & f_req & ~wb_we_i;
  end

  always @(posedge clk_i) if (f_past) begin
    // One ack per request: after each request taken, and after nothing else.
    assert (ack == f_req_q);
    // The stall rule: no request is taken in the ack cycle.
    assert (stall == ack);
  end
endmodule
