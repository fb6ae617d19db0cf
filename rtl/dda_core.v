// SPDX-License-Identifier: Apache-2.0
// Ellipse DDA interpolator core (docs/design.md is the contract: ports, registers and
// behaviour edge by edge). Two ellipse integrators (u_int_x, u_int_y) and the third,
// linear, axis' integrator (u_lin_z), three step counters (u_cnt_x, u_cnt_y, u_cnt_z),
// the control (u_ctrl), and here the plane's shared capacity cap_q, the directions
// dir_*_q and the registered step pulses step_*_q.
//
// Impl chooses the implementation of the datapath and control (docs/design.md,
// "Implementations"): "small" (the default, fewest logic cells) or "fast" (derived
// registers that keep the carries one edge ahead). Both are cycle-exact at the ports
// and hold the same architectural registers; formal/ proves them equal to the
// reference core.
//
// The command word cmd_i is sliced with the DDA_CMD_<FIELD>_LSB/_WIDTH macros of the
// generated dda_params.vh, so the widths are fixed by it (localparams, not parameters:
// overriding them would not change the command layout).
`include "dda_params.vh"
`include "dda_assert.vh"

// The default implementation is "small"; defining DDA_IMPL_FAST (verilator/iverilog
// -DDDA_IMPL_FAST, yosys read_verilog -DDDA_IMPL_FAST) makes it "fast" for builds that
// cannot pass a string parameter easily (the CMake harnesses, scripts/vector-bench.sh).
`ifdef DDA_IMPL_FAST
`define DDA_IMPL_DEFAULT "fast"
`else
`define DDA_IMPL_DEFAULT "small"
`endif

module dda_core #(
  parameter Impl = `DDA_IMPL_DEFAULT  // "small" | "fast"
) (
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
  output wire                      dir_z_o,      // 0 = +Z, 1 = -Z
  output wire                      busy_o,
  output wire                      done_o,
  output wire                      err_o,
  output wire                      iter_o,
  // The norm operands of the pacer (rtl/dda_pace.v), from the registers: an axis'
  // integrand while its counter runs and the integrand is positive, else 0; the
  // capacities.
  output wire [`DDA_ACC_WIDTH-1:0] norm_v_x_o,
  output wire [`DDA_ACC_WIDTH-1:0] norm_v_y_o,
  output wire [`DDA_ACC_WIDTH-1:0] norm_v_z_o,
  output wire [`DDA_ACC_WIDTH-1:0] norm_cap_o,
  output wire [`DDA_ACC_WIDTH-1:0] norm_cap_z_o
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

  // Registers of the top.
  reg [AccWidth-1:0] cap_q    /* verilator public_flat_rd */;
  reg                cdir_x_q /* verilator public_flat_rd */;  // the running command's
  reg                cdir_y_q /* verilator public_flat_rd */;  // step directions
  reg                cdir_z_q /* verilator public_flat_rd */;
  reg                dir_x_q  /* verilator public_flat_rd */;  // direction of the last step
  reg                dir_y_q  /* verilator public_flat_rd */;
  reg                dir_z_q  /* verilator public_flat_rd */;
  reg                step_x_q /* verilator public_flat_rd */;
  reg                step_y_q /* verilator public_flat_rd */;
  reg                step_z_q /* verilator public_flat_rd */;

  reg [AccWidth-1:0] cap_d;
  reg                cdir_x_d;
  reg                cdir_y_d;
  reg                cdir_z_d;
  reg                dir_x_d;
  reg                dir_y_d;
  reg                dir_z_d;
  reg                step_x_d;
  reg                step_y_d;
  reg                step_z_d;

  wire load;
  wire iterate;
  wire ovf_x, ovf_y, ovf_z;
  wire ovf_d_x, ovf_d_y;  // the carries after this edge (Impl "fast")
  wire can_x, can_y, can_z;
  wire active_x, active_y, active_z;
  wire active_d_x, active_d_y, active_d_z;
  wire last_x, last_y, last_z;
  wire [AccWidth-1:0] jv_x, jv_y, jv_z, cap_z;

  dda_ctrl u_ctrl (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .ce_i        (ce_i),
    .cmd_valid_i (cmd_valid_i),
    .cmd_ready_o (cmd_ready_o),
    .active_x_i  (active_x),
    .active_y_i  (active_y),
    .active_z_i  (active_z),
    .can_x_i     (can_x),
    .can_y_i     (can_y),
    .can_z_i     (can_z),
    .last_x_i    (last_x),
    .last_y_i    (last_y),
    .last_z_i    (last_z),
    .load_o      (load),
    .iterate_o   (iterate),
    .busy_o      (busy_o),
    .done_o      (done_o),
    .err_o       (err_o),
    .iter_o      (iter_o)
  );

  dda_integrator #(.AccWidth(AccWidth), .Impl(Impl), .IsY(0)) u_int_x (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .load_i     (load),
    .jv_i       (cmd_jv_x),
    .jr_i       (cmd_jr_x),
    .inc_on_x_i (cmd_inc_x_on_x),
    .inc_on_y_i (cmd_inc_x_on_y),
    .cap_cmd_i  (cmd_cap),
    .iterate_i  (iterate),
    .cap_i      (cap_q),
    .active_i   (active_x),
    .active_d_i (active_d_x),
    .ovf_x_i    (ovf_x),
    .ovf_y_i    (ovf_y),
    .ovf_o      (ovf_x),
    .ovf_d_o    (ovf_d_x),
    .ovf_x_d_i  (ovf_d_x),
    .ovf_y_d_i  (ovf_d_y),
    .can_o      (can_x),
    .jv_o       (jv_x)
  );

  dda_integrator #(.AccWidth(AccWidth), .Impl(Impl), .IsY(1)) u_int_y (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .load_i     (load),
    .jv_i       (cmd_jv_y),
    .jr_i       (cmd_jr_y),
    .inc_on_x_i (cmd_inc_y_on_x),
    .inc_on_y_i (cmd_inc_y_on_y),
    .cap_cmd_i  (cmd_cap),
    .iterate_i  (iterate),
    .cap_i      (cap_q),
    .active_i   (active_y),
    .active_d_i (active_d_y),
    .ovf_x_i    (ovf_x),
    .ovf_y_i    (ovf_y),
    .ovf_o      (ovf_y),
    .ovf_d_o    (ovf_d_y),
    .ovf_x_d_i  (ovf_d_x),
    .ovf_y_d_i  (ovf_d_y),
    .can_o      (can_y),
    .jv_o       (jv_y)
  );

  dda_counter #(.CntWidth(CntWidth), .Impl(Impl)) u_cnt_x (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .load_i    (load),
    .cnt_i     (cmd_cnt_x),
    .iterate_i (iterate),
    .dec_i     (ovf_x),
    .active_o  (active_x),
    .active_d_o(active_d_x),
    .last_o    (last_x)
  );

  dda_counter #(.CntWidth(CntWidth), .Impl(Impl)) u_cnt_y (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .load_i    (load),
    .cnt_i     (cmd_cnt_y),
    .iterate_i (iterate),
    .dec_i     (ovf_y),
    .active_o  (active_y),
    .active_d_o(active_d_y),
    .last_o    (last_y)
  );

  dda_linear #(.AccWidth(AccWidth), .Impl(Impl)) u_lin_z (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .load_i     (load),
    .jv_i       (cmd_jv_z),
    .jr_i       (cmd_jr_z),
    .cap_i      (cmd_cap_z),
    .iterate_i  (iterate),
    .active_i   (active_z),
    .active_d_i (active_d_z),
    .ovf_o      (ovf_z),
    .can_o      (can_z),
    .jv_o       (jv_z),
    .cap_o      (cap_z)
  );

  dda_counter #(.CntWidth(CntWidth), .Impl(Impl)) u_cnt_z (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .load_i    (load),
    .cnt_i     (cmd_cnt_z),
    .iterate_i (iterate),
    .dec_i     (ovf_z),
    .active_o  (active_z),
    .active_d_o(active_d_z),
    .last_o    (last_z)
  );

  // A step pulse carries the direction of the command that made it: dir_*_q changes
  // only together with a step, so a command loaded on the edge of the previous one's
  // last step (back to back) cannot change the direction of that step.
  always @(*) begin
    cap_d    = cap_q;
    cdir_x_d = cdir_x_q;
    cdir_y_d = cdir_y_q;
    cdir_z_d = cdir_z_q;
    if (load) begin
      cap_d    = cmd_cap;
      cdir_x_d = cmd_dir_x;
      cdir_y_d = cmd_dir_y;
      cdir_z_d = cmd_dir_z;
    end
    step_x_d = iterate & ovf_x;  // pulses: 0 unless this edge iterates
    step_y_d = iterate & ovf_y;
    step_z_d = iterate & ovf_z;
    dir_x_d  = step_x_d ? cdir_x_q : dir_x_q;
    dir_y_d  = step_y_d ? cdir_y_q : dir_y_q;
    dir_z_d  = step_z_d ? cdir_z_q : dir_z_q;
  end

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      cap_q    <= {AccWidth{1'b0}};
      cdir_x_q <= 1'b0;
      cdir_y_q <= 1'b0;
      cdir_z_q <= 1'b0;
      dir_x_q  <= 1'b0;
      dir_y_q  <= 1'b0;
      dir_z_q  <= 1'b0;
      step_x_q <= 1'b0;
      step_y_q <= 1'b0;
      step_z_q <= 1'b0;
    end else begin
      cap_q    <= cap_d;
      cdir_x_q <= cdir_x_d;
      cdir_y_q <= cdir_y_d;
      cdir_z_q <= cdir_z_d;
      dir_x_q  <= dir_x_d;
      dir_y_q  <= dir_y_d;
      dir_z_q  <= dir_z_d;
      step_x_q <= step_x_d;
      step_y_q <= step_y_d;
      step_z_q <= step_z_d;
    end
  end

  assign norm_v_x_o   = active_x && !jv_x[AccWidth-1] ? jv_x : {AccWidth{1'b0}};
  assign norm_v_y_o   = active_y && !jv_y[AccWidth-1] ? jv_y : {AccWidth{1'b0}};
  assign norm_v_z_o   = active_z && !jv_z[AccWidth-1] ? jv_z : {AccWidth{1'b0}};
  assign norm_cap_o   = cap_q;
  assign norm_cap_z_o = cap_z;

  assign step_x_o = step_x_q;
  assign step_y_o = step_y_q;
  assign dir_x_o  = dir_x_q;
  assign dir_y_o  = dir_y_q;
  assign step_z_o = step_z_q;
  assign dir_z_o  = dir_z_q;

`ifndef SYNTHESIS
  // Assertions (rtl/dda_assert.vh): a direction register changes only with a step of
  // its axis; steps only on iterations (one pulse per axis and iteration); a loaded
  // command is well formed (0 < cap < 2^(AccWidth-1), jr < cap, and so for a moving Z
  // axis with jv_z <= cap_z: the planner's guarantee, docs/design.md).
  wire cmd_cap_ok = cmd_cap != {AccWidth{1'b0}} && !cmd_cap[AccWidth-1];
  wire cmd_cap_z_ok = cmd_cap_z != {AccWidth{1'b0}} && !cmd_cap_z[AccWidth-1];
  always @(posedge clk_i) begin
    if (rst_ni) begin
      `DDA_ASSERT(dir_x_d == dir_x_q || step_x_d, "ASSERTION dda_core: dir_x_q changes without an X step")
      `DDA_ASSERT(dir_y_d == dir_y_q || step_y_d, "ASSERTION dda_core: dir_y_q changes without a Y step")
      `DDA_ASSERT(dir_z_d == dir_z_q || step_z_d, "ASSERTION dda_core: dir_z_q changes without a Z step")
      `DDA_ASSERT((!step_x_q && !step_y_q && !step_z_q) || iter_o, "ASSERTION dda_core: a step without an iteration")
      `DDA_ASSERT(!load || (cmd_cap_ok && cmd_jr_x < cmd_cap && cmd_jr_y < cmd_cap),
                  "ASSERTION dda_core: a loaded command is malformed (needs 0 < cap < 2^(AccWidth-1), jr < cap)")
      `DDA_ASSERT(!load || cmd_cnt_z == {CntWidth{1'b0}} || (cmd_cap_z_ok && cmd_jr_z < cmd_cap_z && cmd_jv_z <= cmd_cap_z),
                  "ASSERTION dda_core: a loaded Z command is malformed (needs 0 < cap_z < 2^(AccWidth-1), jr_z < cap_z, jv_z <= cap_z)")
    end
  end
`endif

endmodule
