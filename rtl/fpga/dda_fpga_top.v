// SPDX-License-Identifier: Apache-2.0
// FPGA wrapper for synthesis figures (scripts/synth): the command word is far wider
// than a package's pins, so it is shifted in one bit per clock (cmd_bit_i while
// cmd_shift_i is high, least significant bit first) and offered to the core with
// cmd_valid_i. Outputs are the core's own registered outputs. Not part of the IP: it
// exists so that place and route sees the core with realistic I/O.
`include "dda_params.vh"

module dda_fpga_top (
  input  wire clk_i,
  input  wire rst_ni,
  input  wire ce_i,
  input  wire cmd_shift_i,
  input  wire cmd_bit_i,
  input  wire cmd_valid_i,
  output wire cmd_ready_o,
  output wire step_x_o,
  output wire step_y_o,
  output wire dir_x_o,
  output wire dir_y_o,
  output wire busy_o,
  output wire done_o,
  output wire err_o,
  output wire iter_o
);

  reg [`DDA_CMD_WIDTH-1:0] cmd_q;

  always @(posedge clk_i) begin
    if (cmd_shift_i) cmd_q <= {cmd_bit_i, cmd_q[`DDA_CMD_WIDTH-1:1]};
  end

  dda_core u_core (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .ce_i        (ce_i),
    .cmd_valid_i (cmd_valid_i),
    .cmd_ready_o (cmd_ready_o),
    .cmd_i       (cmd_q),
    .step_x_o    (step_x_o),
    .step_y_o    (step_y_o),
    .dir_x_o     (dir_x_o),
    .dir_y_o     (dir_y_o),
    .busy_o      (busy_o),
    .done_o      (done_o),
    .err_o       (err_o),
    .iter_o      (iter_o)
  );

endmodule
