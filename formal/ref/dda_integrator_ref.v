// SPDX-License-Identifier: Apache-2.0
// The reference core for the formal equivalence proofs (scripts/formal.sh): dda_core as
// it was before the fast and small implementations (commit 7e45f85), modules
// renamed with a _ref suffix. Not part of the IP; do not edit: the proofs show that
// rtl/dda_core.v (each Impl) is equal to this at the ports, edge by edge.
// One DDA integrator (docs/design.md, "Integrator"): integrand jv_q, accumulator jr_q
// and the two integrand corrections inc_on_x_q, inc_on_y_q.
//
// Combinationally: sum = jr_q + jv_q (AccWidth + 1 bits) and the carry
// ovf_o = add & (sum >= cap_i), where add = active_i and the integrand is not negative
// (top bit clear). On an iteration (iterate_i) the accumulator keeps sum - cap_i if it
// carried, sum if it did not, and holds if the axis does not add; the
// integrand adds the corrections selected by both axes' carries of the same iteration,
// modulo 2^AccWidth (the corrections are two's complement).
`include "dda_params.vh"

module dda_integrator_ref #(
  parameter integer AccWidth = `DDA_ACC_WIDTH
) (
  input  wire                clk_i,
  input  wire                rst_ni,       // synchronous, active low
  // load a command (cmd_valid_i && cmd_ready_o; may coincide with the last iteration,
  // and then takes precedence)
  input  wire                load_i,
  input  wire [AccWidth-1:0] jv_i,
  input  wire [AccWidth-1:0] jr_i,
  input  wire [AccWidth-1:0] inc_on_x_i,
  input  wire [AccWidth-1:0] inc_on_y_i,
  // iterate (run, ce_i high, neither finished nor stalled)
  input  wire                iterate_i,
  input  wire [AccWidth-1:0] cap_i,        // shared capacity (dda_core_ref.cap_q)
  input  wire                active_i,     // this axis' counter is non-zero
  input  wire                ovf_x_i,      // X carry of this iteration
  input  wire                ovf_y_i,      // Y carry of this iteration
  output wire                ovf_o,        // this integrator's carry
  output wire                can_o         // active and non-zero integrand: can still carry
);

  reg [AccWidth-1:0] jv_q       /* verilator public_flat_rd */;
  reg [AccWidth-1:0] jr_q       /* verilator public_flat_rd */;
  reg [AccWidth-1:0] inc_on_x_q /* verilator public_flat_rd */;
  reg [AccWidth-1:0] inc_on_y_q /* verilator public_flat_rd */;

  reg [AccWidth-1:0] jv_d;
  reg [AccWidth-1:0] jr_d;
  reg [AccWidth-1:0] inc_on_x_d;
  reg [AccWidth-1:0] inc_on_y_d;

  // The adder is one bit wider than the registers: jr_q + jv_q < 2^(AccWidth + 1).
  wire [AccWidth:0] sum /* verilator public_flat_rd */ = {1'b0, jr_q} + {1'b0, jv_q};
  // (sum - cap_i) mod 2^AccWidth: only the low AccWidth bits are stored.
  wire [AccWidth-1:0] sum_minus_cap = sum[AccWidth-1:0] - cap_i;
  wire [AccWidth-1:0] corr_x = ovf_x_i ? inc_on_x_q : {AccWidth{1'b0}};
  wire [AccWidth-1:0] corr_y = ovf_y_i ? inc_on_y_q : {AccWidth{1'b0}};

  // A negative integrand (top bit set) holds its axis: no add, no carry.
  wire add = active_i & ~jv_q[AccWidth-1];
  assign ovf_o = add & (sum >= {1'b0, cap_i});
  assign can_o = add & (jv_q != {AccWidth{1'b0}});

  always @(*) begin
    jv_d       = jv_q;
    jr_d       = jr_q;
    inc_on_x_d = inc_on_x_q;
    inc_on_y_d = inc_on_y_q;
    if (load_i) begin
      jv_d       = jv_i;
      jr_d       = jr_i;
      inc_on_x_d = inc_on_x_i;
      inc_on_y_d = inc_on_y_i;
    end else if (iterate_i) begin
      if (add) begin
        jr_d = ovf_o ? sum_minus_cap : sum[AccWidth-1:0];
      end
      jv_d = jv_q + corr_x + corr_y;
    end
  end

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      jv_q       <= {AccWidth{1'b0}};
      jr_q       <= {AccWidth{1'b0}};
      inc_on_x_q <= {AccWidth{1'b0}};
      inc_on_y_q <= {AccWidth{1'b0}};
    end else begin
      jv_q       <= jv_d;
      jr_q       <= jr_d;
      inc_on_x_q <= inc_on_x_d;
      inc_on_y_q <= inc_on_y_d;
    end
  end

endmodule
