// SPDX-License-Identifier: Apache-2.0
// The reference of the third axis' integrator for the formal equivalence proofs
// (scripts/formal.sh): the behaviour of rtl/dda_linear.v written as plainly as it
// reads in docs/design.md, with no implementation choice. Not part of the IP.
`include "dda_params.vh"

module dda_linear_ref #(
  parameter integer AccWidth = `DDA_ACC_WIDTH
) (
  input  wire                clk_i,
  input  wire                rst_ni,
  input  wire                load_i,
  input  wire [AccWidth-1:0] jv_i,
  input  wire [AccWidth-1:0] jr_i,
  input  wire [AccWidth-1:0] cap_i,
  input  wire                iterate_i,
  input  wire                active_i,
  output wire                ovf_o,
  output wire                can_o
);
  reg [AccWidth-1:0] jv_q, jr_q, cap_q;
  wire [AccWidth:0] sum = {1'b0, jr_q} + {1'b0, jv_q};
  assign ovf_o = active_i && sum >= {1'b0, cap_q};
  assign can_o = active_i && jv_q != {AccWidth{1'b0}};
  wire [AccWidth:0] left = sum - {1'b0, cap_q};
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      jv_q  <= {AccWidth{1'b0}};
      jr_q  <= {AccWidth{1'b0}};
      cap_q <= {AccWidth{1'b0}};
    end else if (load_i) begin
      jv_q  <= jv_i;
      jr_q  <= jr_i;
      cap_q <= cap_i;
    end else if (iterate_i && active_i) begin
      jr_q <= ovf_o ? left[AccWidth-1:0] : sum[AccWidth-1:0];
    end
  end
endmodule
