// SPDX-License-Identifier: Apache-2.0
// Add and select in one logic cell per bit (the small implementation, docs/design.md
// "Implementations"): s = sel ? a + b + ci : a (mod 2^Width), co = the carry out of
// a + b + ci, whatever sel is. sel only chooses the output, so the carry chain does not
// wait for it, and sel may be derived from co itself.
// An iCE40 logic cell holds a LUT4 and a carry cell that share the LUT's inputs I1, I2
// and I3 (carry in); a plain adder leaves I0 unused and a multiplexer after it takes a
// LUT of its own. Under DDA_ICE40 (scripts/synth, scripts/synth-check.sh) each bit is
// placed by hand: SB_LUT4 with I0 = sel and SB_CARRY, one logic cell. Otherwise (every
// simulator and the formal proofs) the same function in plain Verilog; the test
// rtl.ice40_cells simulates both against each other with Yosys' models of the cells.
module dda_addsel #(
  parameter integer Width = 51
) (
  input  wire [Width-1:0] a_i,
  input  wire [Width-1:0] b_i,
  input  wire             ci_i,
  input  wire             sel_i,
  output wire [Width-1:0] s_o,
  output wire             co_o
);
`ifdef DDA_ICE40
  wire [Width:0] c;
  assign c[0] = ci_i;
  genvar i;
  for (i = 0; i < Width; i = i + 1) begin : g_bit
    // O = I0 ? I1 ^ I2 ^ I3 : I1 (INIT bit {I3, I2, I1, I0}).
    SB_LUT4 #(.LUT_INIT(16'hC66C)) u_lut (
      .I0(sel_i), .I1(a_i[i]), .I2(b_i[i]), .I3(c[i]), .O(s_o[i])
    );
    SB_CARRY u_carry (.I0(a_i[i]), .I1(b_i[i]), .CI(c[i]), .CO(c[i+1]));
  end
  assign co_o = c[Width];
`else
  wire [Width:0] s = {1'b0, a_i} + {1'b0, b_i} + {{Width{1'b0}}, ci_i};
  assign s_o  = sel_i ? s[Width-1:0] : a_i;
  assign co_o = s[Width];
`endif
endmodule
