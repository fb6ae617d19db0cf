// SPDX-License-Identifier: Apache-2.0
// Carry-select adder (used by the fast implementation, docs/design.md "Implementations"):
// s = a + b mod 2^Width, the upper Width - Split bits computed for both carries from
// the lower part and chosen by it, so the carry runs through at most max(Split,
// Width - Split) + 1 cells of a carry chain instead of Width.
// The core's formal proofs (scripts/formal.sh) read it with DDA_FORMAL_ABSTRACT defined,
// where it is the plain sum: the job "lemmas" proves that both are equal at the widths
// the core uses, so the proofs of the core may reason on the sum (a solver sees through
// a + b, not through the carry-select structure).
module dda_add #(
  parameter integer Width = 52,
  parameter integer Split = 26
) (
  input  wire [Width-1:0] a_i,
  input  wire [Width-1:0] b_i,
  output wire [Width-1:0] s_o
);
`ifdef DDA_FORMAL_ABSTRACT
  assign s_o = a_i + b_i;
`else
  localparam integer Hi = Width - Split;
  wire [Split:0] lo  = {1'b0, a_i[Split-1:0]} + {1'b0, b_i[Split-1:0]};
  wire [Hi-1:0]  hi0 = a_i[Width-1:Split] + b_i[Width-1:Split];
  // The same sum with a carry in: a 1 appended below both operands carries into bit 0.
  wire [Hi:0]    hi1 = {a_i[Width-1:Split], 1'b1} + {b_i[Width-1:Split], 1'b1};
  assign s_o = {lo[Split] ? hi1[Hi:1] : hi0, lo[Split-1:0]};
  wire unused = hi1[0];
`endif
endmodule
