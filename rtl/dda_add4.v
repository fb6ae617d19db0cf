// SPDX-License-Identifier: Apache-2.0
// s = a + b + c + d mod 2^Width: two carry-save layers (one LUT each) and one
// carry-select adder. Plain sum under DDA_FORMAL_ABSTRACT (proven equal: "lemmas").
module dda_add4 #(
  parameter integer Width = 52
) (
  input  wire [Width-1:0] a_i,
  input  wire [Width-1:0] b_i,
  input  wire [Width-1:0] c_i,
  input  wire [Width-1:0] d_i,
  output wire [Width-1:0] s_o
);
`ifdef DDA_FORMAL_ABSTRACT
  assign s_o = a_i + b_i + c_i + d_i;
`else
  wire [Width-1:0] s1 = a_i ^ b_i ^ c_i;
  wire [Width-2:0] m1 = (a_i[Width-2:0] & b_i[Width-2:0]) | (a_i[Width-2:0] & c_i[Width-2:0]) |
                        (b_i[Width-2:0] & c_i[Width-2:0]);
  wire [Width-1:0] k1 = {m1, 1'b0};
  wire [Width-1:0] s2 = s1 ^ k1 ^ d_i;
  wire [Width-2:0] m2 = (s1[Width-2:0] & k1[Width-2:0]) | (s1[Width-2:0] & d_i[Width-2:0]) |
                        (k1[Width-2:0] & d_i[Width-2:0]);
  dda_add #(.Width(Width), .Split(Width / 2)) u_add (.a_i(s2), .b_i({m2, 1'b0}), .s_o(s_o));
`endif
endmodule
