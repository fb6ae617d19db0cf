// SPDX-License-Identifier: Apache-2.0
// Properties of one implementation of dda_core (scripts/formal.sh props|cover): the
// assertions written beside the logic in rtl/ (DDA_ASSERT, read as formal assertions)
// under the driver's guarantees (dda_env.vh), and the cover traces. The core is
// flattened and its architectural registers exposed as outputs a_<name> before this is
// read (the environment constrains some of them).
`include "dda_params.vh"

module dda_formal_props (
  input wire                      clk_i,
  input wire                      rst_ni,
  input wire                      ce_i,
  input wire                      cmd_valid_i,
  input wire [`DDA_CMD_WIDTH-1:0] cmd_i
);
  localparam integer W = `DDA_ACC_WIDTH;
  localparam integer C = `DDA_CNT_WIDTH;

  wire cmd_ready, step_x, step_y, dir_x, dir_y, step_z, dir_z, busy, done, err, iter;
  wire [W-1:0] s_jv_x, s_jv_y, s_jr_x, s_cap, s_inc_xx, s_inc_xy, s_inc_yx, s_inc_yy;
  wire [C-1:0] s_cnt_x, s_cnt_y;

  dda_core dut (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    .ce_i           (ce_i),
    .cmd_valid_i    (cmd_valid_i),
    .cmd_ready_o    (cmd_ready),
    .cmd_i          (cmd_i),
    .step_x_o       (step_x),
    .step_y_o       (step_y),
    .dir_x_o        (dir_x),
    .dir_y_o        (dir_y),
    .step_z_o       (step_z),
    .dir_z_o        (dir_z),
    .busy_o         (busy),
    .done_o         (done),
    .err_o          (err),
    .iter_o         (iter),
    .a_u_int_x_jv_q (s_jv_x),
    .a_u_int_y_jv_q (s_jv_y),
    .a_u_int_x_jr_q (s_jr_x),
    .a_cap_q        (s_cap),
    .a_u_cnt_x_cnt_q(s_cnt_x),
    .a_u_cnt_y_cnt_q(s_cnt_y),
    .a_u_int_x_inc_on_x_q(s_inc_xx),
    .a_u_int_x_inc_on_y_q(s_inc_xy),
    .a_u_int_y_inc_on_x_q(s_inc_yx),
    .a_u_int_y_inc_on_y_q(s_inc_yy)
  );
  wire s_step_x = step_x, s_step_y = step_y, s_iter = iter;

`include "dda_env.vh"

  // The properties are the assertions beside the logic in rtl/ (done and err never
  // together, busy iff running, ... : see scripts/formal-mutants.sh for the list).

  // Covers (scripts/formal.sh cover): each must be reached within the depth.
  reg [1:0] n_load = 2'd0;  // commands loaded since reset, saturating
  always @(posedge clk_i) begin
    if (!rst_ni) n_load <= 2'd0;
    else if (env_load && n_load != 2'd3) n_load <= n_load + 2'd1;
  end
  wire neg_x = s_jv_x[W-1];
  always @(*) begin
    if (!$initstate && rst_ni) begin
      // a back-to-back load: the next command taken on the finishing edge of a running one
      cover (env_load && busy && n_load == 2'd1);
      // a stall ending in err_o
      cover (err);
      // a third-axis step
      cover (step_z);
      // a negative integrand holding its axis: an iteration with X active and negative
      cover (busy && ce_i && s_cnt_x != {C{1'b0}} && neg_x && s_cnt_y != {C{1'b0}} && !s_jv_y[W-1] &&
             s_jv_y != {W{1'b0}});
    end
  end
endmodule
