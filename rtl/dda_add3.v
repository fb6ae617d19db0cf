// SPDX-License-Identifier: Apache-2.0
// s = a + b + c + ci mod 2^Width: one carry-save layer (one LUT) and one carry-select
// adder; the carry in takes the free low bit of the shifted carries. Plain sum under
// DDA_FORMAL_ABSTRACT (proven equal: scripts/formal.sh lemmas).
module dda_add3 #(
  parameter integer Width = 52
) (
  input  wire [Width-1:0] a_i,
  input  wire [Width-1:0] b_i,
  input  wire [Width-1:0] c_i,
  input  wire             ci_i,
  output wire [Width-1:0] s_o
);
`ifdef DDA_FORMAL_ABSTRACT
  assign s_o = a_i + b_i + c_i + {{(Width-1){1'b0}}, ci_i};
`else
  wire [Width-1:0] s1 = a_i ^ b_i ^ c_i;
  wire [Width-2:0] m1 = (a_i[Width-2:0] & b_i[Width-2:0]) | (a_i[Width-2:0] & c_i[Width-2:0]) |
                        (b_i[Width-2:0] & c_i[Width-2:0]);
  dda_add #(.Width(Width), .Split(Width / 2)) u_add (.a_i(s1), .b_i({m1, ci_i}), .s_o(s_o));
`endif
endmodule
