// SPDX-License-Identifier: Apache-2.0
// The iCE40 LUT (SB_LUT4) as Yosys' model (ice40/cells_sim.v) computes it, and which of
// its 16 input combinations it had at the board bench's clock edges: at the end of the
// run each instance prints "LUTCOV <instance> <mask>", bit k of the mask set when the
// inputs were combination k ({I3, I2, I1, I0}). For scripts/board-sim.sh --lut-coverage
// in place of Yosys' model; scripts/netlist_mutants.py --coverage-report reads the lines.
// The inputs are sampled on the bench's clock (dda_board_tb.clk, the block's clock
// through the PLL model), not on every change: a glitch between edges is not a
// combination the logic acts on.
module SB_LUT4 (
  output wire O,
  input  wire I0,
  input  wire I1,
  input  wire I2,
  input  wire I3
);
  parameter [15:0] LUT_INIT = 16'h0000;
  // (Yosys' mux tree: an unknown select with equal halves gives their value)
  wire [7:0] s3 = I3 ? LUT_INIT[15:8] : LUT_INIT[7:0];
  wire [3:0] s2 = I2 ? s3[7:4] : s3[3:0];
  wire [1:0] s1 = I1 ? s2[3:2] : s2[1:0];
  assign O = I0 ? s1[1] : s1[0];

  reg [15:0] seen = 16'h0000;
  always @(posedge dda_board_tb.clk)
    if (^{I3, I2, I1, I0} !== 1'bx) seen[{I3, I2, I1, I0}] <= 1'b1;
  final $display("LUTCOV %m %h", seen);
endmodule
