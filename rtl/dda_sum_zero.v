// SPDX-License-Identifier: Apache-2.0
// z = (a + b == 0 mod 2^Width) without a carry chain: every bit of the sum is 0 iff the
// carry into it is a | b of the bit below (0 into bit 0). Plain test under
// DDA_FORMAL_ABSTRACT (proven equal: "lemmas").
module dda_sum_zero #(
  parameter integer Width = 51
) (
  input  wire [Width-1:0] a_i,
  input  wire [Width-1:0] b_i,
  output wire             z_o
);
`ifdef DDA_FORMAL_ABSTRACT
  assign z_o = a_i + b_i == {Width{1'b0}};
`else
  wire [Width-1:0] c = {a_i[Width-2:0] | b_i[Width-2:0], 1'b0};
  assign z_o = &(~(a_i ^ b_i ^ c));
`endif
endmodule
