// SPDX-License-Identifier: Apache-2.0
// The reference core for the formal equivalence proofs (scripts/formal.sh): dda_core as
// it was before the fast and small implementations (commit 7e45f85), modules
// renamed with a _ref suffix. Not part of the IP; do not edit: the proofs show that
// rtl/dda_core.v (each Impl) is equal to this at the ports, edge by edge.
// The third axis was added to it as plainly as it reads in docs/design.md: its
// integrator dda_linear_ref, its counter, directions and step register, and its
// activity, carry ability and last step folded into the Y inputs of the unchanged
// control (finished, stalled and finishing then read all three axes).
// Ellipse DDA interpolator core (docs/design.md is the contract: ports, registers and
// behaviour edge by edge). Two integrators (u_int_x, u_int_y), two step counters
// (u_cnt_x, u_cnt_y), the control (u_ctrl), and here the shared capacity cap_q, the
// directions dir_*_q and the registered step pulses step_*_q.
//
// The command word cmd_i is sliced with the DDA_CMD_<FIELD>_LSB/_WIDTH macros of the
// generated dda_params.vh, so the widths are fixed by it (localparams, not parameters:
// overriding them would not change the command layout).
`include "dda_params.vh"
`include "dda_assert.vh"

module dda_core_ref (
  input  wire                      clk_i,
  input  wire                      rst_ni,       // synchronous, active low
  input  wire                      ce_i,         // one iteration per edge while high
  input  wire                      cmd_valid_i,
  output wire                      cmd_ready_o,
  input  wire [`DDA_CMD_WIDTH-1:0] cmd_i,
  output wire                      step_x_o,
  output wire                      step_y_o,
  output wire                      dir_x_o,      // 0 = +X, 1 = -X
  output wire                      dir_y_o,      // 0 = +Y, 1 = -Y
  output wire                      step_z_o,
  output wire                      dir_z_o,
  output wire                      busy_o,
  output wire                      done_o,
  output wire                      err_o,
  output wire                      iter_o
);

  localparam integer AccWidth = `DDA_ACC_WIDTH;
  localparam integer CntWidth = `DDA_CNT_WIDTH;

  // Command fields.
  wire [AccWidth-1:0] cmd_jv_x       = cmd_i[`DDA_CMD_JV_X_LSB +: `DDA_CMD_JV_X_WIDTH];
  wire [AccWidth-1:0] cmd_jv_y       = cmd_i[`DDA_CMD_JV_Y_LSB +: `DDA_CMD_JV_Y_WIDTH];
  wire [AccWidth-1:0] cmd_jr_x       = cmd_i[`DDA_CMD_JR_X_LSB +: `DDA_CMD_JR_X_WIDTH];
  wire [AccWidth-1:0] cmd_jr_y       = cmd_i[`DDA_CMD_JR_Y_LSB +: `DDA_CMD_JR_Y_WIDTH];
  wire [AccWidth-1:0] cmd_cap        = cmd_i[`DDA_CMD_CAP_LSB +: `DDA_CMD_CAP_WIDTH];
  wire [CntWidth-1:0] cmd_cnt_x      = cmd_i[`DDA_CMD_CNT_X_LSB +: `DDA_CMD_CNT_X_WIDTH];
  wire [CntWidth-1:0] cmd_cnt_y      = cmd_i[`DDA_CMD_CNT_Y_LSB +: `DDA_CMD_CNT_Y_WIDTH];
  wire                cmd_dir_x      = cmd_i[`DDA_CMD_DIR_X_LSB];
  wire                cmd_dir_y      = cmd_i[`DDA_CMD_DIR_Y_LSB];
  wire [AccWidth-1:0] cmd_inc_x_on_x = cmd_i[`DDA_CMD_INC_X_ON_X_LSB +: `DDA_CMD_INC_X_ON_X_WIDTH];
  wire [AccWidth-1:0] cmd_inc_x_on_y = cmd_i[`DDA_CMD_INC_X_ON_Y_LSB +: `DDA_CMD_INC_X_ON_Y_WIDTH];
  wire [AccWidth-1:0] cmd_inc_y_on_x = cmd_i[`DDA_CMD_INC_Y_ON_X_LSB +: `DDA_CMD_INC_Y_ON_X_WIDTH];
  wire [AccWidth-1:0] cmd_inc_y_on_y = cmd_i[`DDA_CMD_INC_Y_ON_Y_LSB +: `DDA_CMD_INC_Y_ON_Y_WIDTH];
  wire [AccWidth-1:0] cmd_jv_z       = cmd_i[`DDA_CMD_JV_Z_LSB +: `DDA_CMD_JV_Z_WIDTH];
  wire [AccWidth-1:0] cmd_jr_z       = cmd_i[`DDA_CMD_JR_Z_LSB +: `DDA_CMD_JR_Z_WIDTH];
  wire [AccWidth-1:0] cmd_cap_z      = cmd_i[`DDA_CMD_CAP_Z_LSB +: `DDA_CMD_CAP_Z_WIDTH];
  wire [CntWidth-1:0] cmd_cnt_z      = cmd_i[`DDA_CMD_CNT_Z_LSB +: `DDA_CMD_CNT_Z_WIDTH];
  wire                cmd_dir_z      = cmd_i[`DDA_CMD_DIR_Z_LSB];
  reg                 cdir_z_q, dir_z_q, step_z_q;
  wire                ovf_z, can_z, active_z, last_z;

  // Registers of the top.
  reg [AccWidth-1:0] cap_q    /* verilator public_flat_rd */;
  reg                cdir_x_q /* verilator public_flat_rd */;  // the running command's
  reg                cdir_y_q /* verilator public_flat_rd */;  // step directions
  reg                dir_x_q  /* verilator public_flat_rd */;  // direction of the last step
  reg                dir_y_q  /* verilator public_flat_rd */;
  reg                step_x_q /* verilator public_flat_rd */;
  reg                step_y_q /* verilator public_flat_rd */;

  reg [AccWidth-1:0] cap_d;
  reg                cdir_x_d;
  reg                cdir_y_d;
  reg                dir_x_d;
  reg                dir_y_d;
  reg                step_x_d;
  reg                step_y_d;

  wire load;
  wire iterate;
  wire ovf_x, ovf_y;
  wire can_x, can_y;
  wire active_x, active_y;
  wire last_x, last_y;

  dda_ctrl_ref u_ctrl (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .ce_i        (ce_i),
    .cmd_valid_i (cmd_valid_i),
    .cmd_ready_o (cmd_ready_o),
    .active_x_i  (active_x),
    .active_y_i  (active_y | active_z),
    .can_x_i     (can_x),
    .can_y_i     (can_y | can_z),
    .last_x_i    (last_x),
    .last_y_i    (last_y & last_z),
    .load_o      (load),
    .iterate_o   (iterate),
    .busy_o      (busy_o),
    .done_o      (done_o),
    .err_o       (err_o),
    .iter_o      (iter_o)
  );

  dda_integrator_ref #(.AccWidth(AccWidth)) u_int_x (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .load_i     (load),
    .jv_i       (cmd_jv_x),
    .jr_i       (cmd_jr_x),
    .inc_on_x_i (cmd_inc_x_on_x),
    .inc_on_y_i (cmd_inc_x_on_y),
    .iterate_i  (iterate),
    .cap_i      (cap_q),
    .active_i   (active_x),
    .ovf_x_i    (ovf_x),
    .ovf_y_i    (ovf_y),
    .ovf_o      (ovf_x),
    .can_o      (can_x)
  );

  dda_integrator_ref #(.AccWidth(AccWidth)) u_int_y (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .load_i     (load),
    .jv_i       (cmd_jv_y),
    .jr_i       (cmd_jr_y),
    .inc_on_x_i (cmd_inc_y_on_x),
    .inc_on_y_i (cmd_inc_y_on_y),
    .iterate_i  (iterate),
    .cap_i      (cap_q),
    .active_i   (active_y),
    .ovf_x_i    (ovf_x),
    .ovf_y_i    (ovf_y),
    .ovf_o      (ovf_y),
    .can_o      (can_y)
  );

  dda_counter_ref #(.CntWidth(CntWidth)) u_cnt_x (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .load_i    (load),
    .cnt_i     (cmd_cnt_x),
    .iterate_i (iterate),
    .dec_i     (ovf_x),
    .active_o  (active_x),
    .last_o    (last_x)
  );

  dda_counter_ref #(.CntWidth(CntWidth)) u_cnt_y (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .load_i    (load),
    .cnt_i     (cmd_cnt_y),
    .iterate_i (iterate),
    .dec_i     (ovf_y),
    .active_o  (active_y),
    .last_o    (last_y)
  );

  dda_linear_ref #(.AccWidth(AccWidth)) u_lin_z (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .load_i    (load),
    .jv_i      (cmd_jv_z),
    .jr_i      (cmd_jr_z),
    .cap_i     (cmd_cap_z),
    .iterate_i (iterate),
    .active_i  (active_z),
    .ovf_o     (ovf_z),
    .can_o     (can_z)
  );

  dda_counter_ref #(.CntWidth(CntWidth)) u_cnt_z (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .load_i    (load),
    .cnt_i     (cmd_cnt_z),
    .iterate_i (iterate),
    .dec_i     (ovf_z),
    .active_o  (active_z),
    .last_o    (last_z)
  );

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      cdir_z_q <= 1'b0;
      dir_z_q  <= 1'b0;
      step_z_q <= 1'b0;
    end else begin
      if (load) cdir_z_q <= cmd_dir_z;
      step_z_q <= iterate & ovf_z;
      if (iterate & ovf_z) dir_z_q <= cdir_z_q;
    end
  end
  assign step_z_o = step_z_q;
  assign dir_z_o  = dir_z_q;

  // A step pulse carries the direction of the command that made it: dir_*_q changes
  // only together with a step, so a command loaded on the edge of the previous one's
  // last step (back to back) cannot change the direction of that step.
  always @(*) begin
    cap_d    = cap_q;
    cdir_x_d = cdir_x_q;
    cdir_y_d = cdir_y_q;
    if (load) begin
      cap_d    = cmd_cap;
      cdir_x_d = cmd_dir_x;
      cdir_y_d = cmd_dir_y;
    end
    step_x_d = iterate & ovf_x;  // pulses: 0 unless this edge iterates
    step_y_d = iterate & ovf_y;
    dir_x_d  = step_x_d ? cdir_x_q : dir_x_q;
    dir_y_d  = step_y_d ? cdir_y_q : dir_y_q;
  end

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      cap_q    <= {AccWidth{1'b0}};
      cdir_x_q <= 1'b0;
      cdir_y_q <= 1'b0;
      dir_x_q  <= 1'b0;
      dir_y_q  <= 1'b0;
      step_x_q <= 1'b0;
      step_y_q <= 1'b0;
    end else begin
      cap_q    <= cap_d;
      cdir_x_q <= cdir_x_d;
      cdir_y_q <= cdir_y_d;
      dir_x_q  <= dir_x_d;
      dir_y_q  <= dir_y_d;
      step_x_q <= step_x_d;
      step_y_q <= step_y_d;
    end
  end

  assign step_x_o = step_x_q;
  assign step_y_o = step_y_q;
  assign dir_x_o  = dir_x_q;
  assign dir_y_o  = dir_y_q;

`ifndef SYNTHESIS
  // Assertions (rtl/dda_assert.vh): a direction register changes only with a step of
  // its axis; a loaded command is well formed (0 < cap < 2^(AccWidth-1), jr < cap: the
  // planner's guarantee, docs/design.md).
  wire cmd_cap_ok = cmd_cap != {AccWidth{1'b0}} && !cmd_cap[AccWidth-1];
  always @(posedge clk_i) begin
    if (rst_ni) begin
      `DDA_ASSERT(dir_x_d == dir_x_q || step_x_d, "ASSERTION dda_core_ref: dir_x_q changes without an X step")
      `DDA_ASSERT(dir_y_d == dir_y_q || step_y_d, "ASSERTION dda_core_ref: dir_y_q changes without a Y step")
      `DDA_ASSERT(!load || (cmd_cap_ok && cmd_jr_x < cmd_cap && cmd_jr_y < cmd_cap),
                  "ASSERTION dda_core_ref: a loaded command is malformed (needs 0 < cap < 2^(AccWidth-1), jr < cap)")
    end
  end
`endif

endmodule
