// SPDX-License-Identifier: Apache-2.0
// Self-checking bench for a per-cycle vector set written by `dda vectors` (docs/vectors.md).
// Runs unchanged under Icarus (iverilog -g2012 + vvp) and Verilator (--binary):
//   +vectors=DIR   the vector set
// Each cycle: apply that cycle's inputs (cmd_i scrambled while cmd_valid_i is low), let
// them settle, sample cmd_ready_o, clock one rising edge, then compare the outputs and every architectural register with the
// expected word (cmd_ready_o only on cycles with rst_ni high). The first mismatch prints "MISMATCH cycle N field F: expected E, got G"
// and ends the run with $fatal; a complete run prints "dda_vec_tb: PASS".
`timescale 1ns / 1ps
`include "dda_params.vh"
`include "dda_vec_fields.vh"

module dda_vec_tb;

  localparam integer MaxCmds = 1 << `DDA_VEC_CMD_ADDR_BITS;

  reg                          clk = 1'b0;
  reg                          rst_n = 1'b0;
  reg                          ce = 1'b0;
  reg                          cmd_valid = 1'b0;
  reg  [`DDA_CMD_WIDTH-1:0]    cmd = {`DDA_CMD_WIDTH{1'b0}};
  wire                         cmd_ready, step_x, step_y, dir_x, dir_y, step_z, dir_z, busy, done, err, iter;

  wire [`DDA_ACC_WIDTH-1:0] norm_v_x, norm_v_y, norm_v_z, norm_cap, norm_cap_z;
  dda_core dut (
    .clk_i       (clk),
    .rst_ni      (rst_n),
    .ce_i        (ce),
    .cmd_valid_i (cmd_valid),
    .cmd_ready_o (cmd_ready),
    .cmd_i       (cmd),
    .step_x_o    (step_x),
    .step_y_o    (step_y),
    .dir_x_o     (dir_x),
    .dir_y_o     (dir_y),
    .step_z_o    (step_z),
    .dir_z_o     (dir_z),
    .busy_o      (busy),
    .done_o      (done),
    .err_o       (err),
    .iter_o      (iter),
    .norm_v_x_o  (norm_v_x),  // the pacer's norm operands: no pacer here
    .norm_v_y_o  (norm_v_y),
    .norm_v_z_o  (norm_v_z),
    .norm_cap_o  (norm_cap),
    .norm_cap_z_o(norm_cap_z)
  );
  wire unused_norm = &{1'b0, norm_v_x, norm_v_y, norm_v_z, norm_cap, norm_cap_z};

  reg [`DDA_CMD_WIDTH-1:0]     cmds [0:MaxCmds-1];
  reg [31:0]                   counts [0:1];
  reg [`DDA_VEC_IN_WIDTH-1:0]  vin;
  reg [`DDA_VEC_EXP_WIDTH-1:0] vexp;
  reg [`DDA_VEC_EXP_WIDTH-1:0] got;
  reg                          ready_pre;
  integer                      fin, fexp, cyc, ncycles, ncmds, r1, r2;
  string                       dir;

  initial begin
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "dda_vec_tb: usage: +vectors=DIR");
    counts[0] = 0;
    counts[1] = 0;
    $readmemh({dir, "/counts.hex"}, counts);
    ncmds = counts[0];
    ncycles = counts[1];
    if (ncmds < 1 || ncmds > MaxCmds || ncycles < 1) begin
      $fatal(1, "dda_vec_tb: %s/counts.hex: %0d commands, %0d cycles (1..%0d commands)", dir, ncmds,
             ncycles, MaxCmds);
    end
    $readmemh({dir, "/cmds.hex"}, cmds, 0, ncmds - 1);
    fin = $fopen({dir, "/cycle_in.hex"}, "r");
    fexp = $fopen({dir, "/cycle_exp.hex"}, "r");
    if (fin == 0 || fexp == 0) $fatal(1, "dda_vec_tb: cannot open the cycle files in %s", dir);
    for (cyc = 0; cyc < ncycles; cyc = cyc + 1) begin
      r1 = $fscanf(fin, "%h\n", vin);
      r2 = $fscanf(fexp, "%h\n", vexp);
      if (r1 != 1 || r2 != 1) $fatal(1, "dda_vec_tb: the cycle files end before cycle %0d", cyc);
      rst_n = vin[`DDA_VEC_IDX_WIDTH + 2];
      ce = vin[`DDA_VEC_IDX_WIDTH + 1];
      cmd_valid = vin[`DDA_VEC_IDX_WIDTH];
      if ({16'd0, vin[`DDA_VEC_IDX_WIDTH-1:0]} >= ncmds) $fatal(1, "dda_vec_tb: cycle %0d offers command %0d of %0d", cyc,
                                                        vin[`DDA_VEC_IDX_WIDTH-1:0], ncmds);
      // While cmd_valid_i is low the core must ignore cmd_i: it carries the offered
      // command rotated, inverted and mixed with the cycle number, so a register that
      // reads cmd_i outside a load shows up as a mismatch.
      cmd = cmds[vin[`DDA_VEC_CMD_ADDR_BITS-1:0]];
      if (!cmd_valid) cmd = ~{cmd[`DDA_CMD_WIDTH-2:0], cmd[`DDA_CMD_WIDTH-1]} ^ {{(`DDA_CMD_WIDTH-32){1'b0}}, cyc[31:0]};
      #4;
      // Before the first reset edge the core's state, and so cmd_ready_o, is unknown:
      // cycles with rst_ni low expect 0 (docs/vectors.md).
      ready_pre = rst_n ? cmd_ready : 1'b0;
      clk = 1'b1;
      #1;
      got = `DDA_VEC_GOT(ready_pre);
      if (got !== vexp) begin
        `DDA_VEC_REPORT(cyc, vexp, got)
        $fatal(1, "dda_vec_tb: FAIL at cycle %0d of %0d (%s)", cyc, ncycles, dir);
      end
      #4;
      clk = 1'b0;
      #1;
    end
    $display("dda_vec_tb: PASS: %0d cycles, %0d commands, every output and register equal (%s)",
             ncycles, ncmds, dir);
    $finish;
  end

endmodule
