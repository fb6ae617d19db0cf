// SPDX-License-Identifier: Apache-2.0
// The lemmas of the core's proofs (scripts/formal.sh lemmas): the arithmetic blocks of
// the fast implementation equal the plain operations they stand for under
// DDA_FORMAL_ABSTRACT, at the widths the core instantiates them with (AccWidth + 1 for
// the sums, AccWidth for the zero test). Read without DDA_FORMAL_ABSTRACT: this proves
// the real structures. And the small implementation's add-and-select cells, read with
// DDA_ICE40 and Yosys' models of SB_LUT4 and SB_CARRY, equal the plain Verilog every
// simulator and the other proofs use: the hand-placed LUT contents are proven.
// Combinational: one step from any inputs.
`include "dda_params.vh"

module dda_formal_lemmas (
  input wire [`DDA_ACC_WIDTH:0]   a,
  input wire [`DDA_ACC_WIDTH:0]   b,
  input wire [`DDA_ACC_WIDTH:0]   c,
  input wire [`DDA_ACC_WIDTH:0]   d
);
  localparam integer W  = `DDA_ACC_WIDTH;
  localparam integer EW = W + 1;

  wire [EW-1:0] s2, s3, s4;
  wire          z;
  dda_add #(.Width(EW), .Split(EW / 2)) u_add (.a_i(a), .b_i(b), .s_o(s2));
  dda_add3 #(.Width(EW)) u_add3 (.a_i(a), .b_i(b), .c_i(c), .ci_i(d[0]), .s_o(s3));
  dda_add4 #(.Width(EW)) u_add4 (.a_i(a), .b_i(b), .c_i(c), .d_i(d), .s_o(s4));
  dda_sum_zero #(.Width(W)) u_zero (.a_i(a[W-1:0]), .b_i(b[W-1:0]), .z_o(z));
  wire [EW-1:0] s5;
  wire          co5;
  wire [EW:0]   full = {1'b0, a} + {1'b0, b} + {{EW{1'b0}}, d[0]};
  dda_addsel #(.Width(EW)) u_addsel (.a_i(a), .b_i(b), .ci_i(d[0]), .sel_i(d[1]), .s_o(s5), .co_o(co5));

  always @(*) begin
    assert (s2 == a + b);
    assert (s3 == a + b + c + {{(EW-1){1'b0}}, d[0]});
    assert (s4 == a + b + c + d);
    assert (z == (a[W-1:0] + b[W-1:0] == {W{1'b0}}));
    assert (s5 == (d[1] ? full[EW-1:0] : a));
    assert (co5 == full[EW]);
  end
endmodule
