// SPDX-License-Identifier: Apache-2.0
// dda_core scoreboarded by the golden model through DPI-C (tb/dpi/dda_dpi.h): a
// SystemVerilog bench to copy into another flow. It plans what +dda_args gives (the
// dda command's options, e.g. +dda_args="--a 10 --b 6 --bits 4 --preload zero" or
// "--program part.ngc"), offers the pieces back to back with ce_i low on about
// +stall=PERCENT of the cycles (a pseudo-random sequence from +seed=N), and before
// every edge compares each output port with the reference model's and, on every
// iteration, the steps and directions with the golden run's record. The clock comes
// from outside (tb/dpi/dpi_main.cpp under Verilator); the bench ends with $finish
// after dda_finish(), whose verdict the program's exit status carries.
`include "dda_params.vh"

module dda_dpi_tb (
  input logic clk
);

  import "DPI-C" function int dda_plan(input string args);
  import "DPI-C" function void dda_piece_command(input int index, output bit [`DDA_CMD_WIDTH-1:0] cmd);
  import "DPI-C" function int dda_ref_edge(input bit rst_n, input bit ce, input bit cmd_valid,
                                           input bit [`DDA_CMD_WIDTH-1:0] cmd);
  import "DPI-C" function int dda_ref_output(input string port, input bit value);
  import "DPI-C" function int dda_check_record(input bit step_x, input bit step_y, input bit step_z,
                                               input bit dir_x, input bit dir_y, input bit dir_z);
  import "DPI-C" function int dda_finish();

  logic rst_n = 1'b0, ce = 1'b0, cmd_valid = 1'b0;
  bit [`DDA_CMD_WIDTH-1:0] cmd = '0;
  wire cmd_ready, step_x, step_y, dir_x, dir_y, step_z, dir_z, busy, done, err, iter;
  wire [`DDA_ACC_WIDTH-1:0] norm_v_x, norm_v_y, norm_v_z, norm_cap, norm_cap_z;

  dda_core u_dut (
    .clk_i(clk), .rst_ni(rst_n), .ce_i(ce), .cmd_valid_i(cmd_valid), .cmd_ready_o(cmd_ready), .cmd_i(cmd),
    .step_x_o(step_x), .step_y_o(step_y), .dir_x_o(dir_x), .dir_y_o(dir_y), .step_z_o(step_z), .dir_z_o(dir_z),
    .busy_o(busy), .done_o(done), .err_o(err), .iter_o(iter),
    .norm_v_x_o(norm_v_x), .norm_v_y_o(norm_v_y), .norm_v_z_o(norm_v_z), .norm_cap_o(norm_cap),
    .norm_cap_z_o(norm_cap_z)
  );

  string args;
  int pieces = 0, next = 0, stall = 20, bad = 0, cycle = 0, failed = 0;
  int unsigned lfsr = 1;
  bit [`DDA_CMD_WIDTH-1:0] word;

  initial begin
    if (!$value$plusargs("dda_args=%s", args)) args = "--a 10 --b 6 --bits 4 --preload zero";
    if (!$value$plusargs("stall=%d", stall)) stall = 20;
    if (!$value$plusargs("seed=%d", lfsr)) lfsr = 1;
    if (lfsr == 0) lfsr = 1;
    pieces = dda_plan(args);
    if (pieces < 0) begin
      failed = 1;
      $display("dda_dpi_tb: the plan was refused: %s", args);
      $finish;
    end
  end

  // Every output before the edge, then the edge in the model with the inputs the core
  // takes now (it compares the outputs first), then the next cycle's inputs.
  always @(posedge clk) begin
    bad += dda_ref_output("cmd_ready_o", cmd_ready);
    bad += dda_ref_output("step_x_o", step_x);
    bad += dda_ref_output("step_y_o", step_y);
    bad += dda_ref_output("dir_x_o", dir_x);
    bad += dda_ref_output("dir_y_o", dir_y);
    bad += dda_ref_output("step_z_o", step_z);
    bad += dda_ref_output("dir_z_o", dir_z);
    bad += dda_ref_output("busy_o", busy);
    bad += dda_ref_output("done_o", done);
    bad += dda_ref_output("err_o", err);
    bad += dda_ref_output("iter_o", iter);
    if (rst_n && iter) bad += dda_check_record(step_x, step_y, step_z, dir_x, dir_y, dir_z);
    bad += dda_ref_edge(rst_n, ce, cmd_valid, cmd);
    if (cmd_valid && cmd_ready) next = next + 1;
    cycle = cycle + 1;
    lfsr = lfsr ^ (lfsr << 13);
    lfsr = lfsr ^ (lfsr >> 17);
    lfsr = lfsr ^ (lfsr << 5);
    rst_n <= cycle >= 2;
    ce <= (lfsr % 100) >= stall;
    cmd_valid <= cycle >= 2 && next < pieces;
    if (next < pieces) begin
      dda_piece_command(next, word);
      cmd <= word;
    end
    if (bad != 0 || (cycle > 3 && next == pieces && !busy && !cmd_valid)) begin
      failed = dda_finish();
      $finish;
    end
  end

endmodule
