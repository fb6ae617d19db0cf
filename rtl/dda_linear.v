// SPDX-License-Identifier: Apache-2.0
// The third axis' integrator (docs/design.md, "Linear integrator"): a linear DDA with a
// constant integrand jv_q, an accumulator jr_q and a capacity cap_q of its own, the
// architectural registers both implementations hold. Bresenham's rule: the axis moves
// jv_q / cap_q steps per iteration, its phase (the preload jr) given by the command,
// so a move split into pieces continues where the piece before it stopped.
//
// Behaviour (both implementations): the carry ovf_o = active_i & (jr_q + jv_q >= cap_q).
// On an iteration (iterate_i) of an active axis the accumulator keeps
// jr_q + jv_q - cap_q if it carried and jr_q + jv_q if it did not; an inactive axis
// holds. The driver guarantees 0 <= jv <= cap < 2^(AccWidth-1) and jr < cap (at most one
// step per iteration; the accumulator stays below the capacity).
//
// Impl (docs/design.md, "Implementations"):
//   "small"  the adder jr_q + jv_q and its compare with cap_q in the cycle (dda_addsel).
//   "fast"   the carry one edge ahead: e_q = jr_q + jv_q - cap_q, jvmc_q = jv_q - cap_q
//            (AccWidth + 1 bits, signed), ovf_q and jvz_q (jv_q == 0); an iteration is
//            one carry chain, e' = e + (ovf ? jvmc : jv).
`include "dda_params.vh"
`include "dda_assert.vh"

module dda_linear #(
  parameter integer AccWidth = `DDA_ACC_WIDTH,
  parameter         Impl     = "small"
) (
  input  wire                clk_i,
  input  wire                rst_ni,       // synchronous, active low
  input  wire                load_i,       // load a command (wins over iterate_i)
  input  wire [AccWidth-1:0] jv_i,
  input  wire [AccWidth-1:0] jr_i,
  input  wire [AccWidth-1:0] cap_i,
  input  wire                iterate_i,    // an iteration happens on this edge
  input  wire                active_i,     // this axis' counter is non-zero
  input  wire                active_d_i,   // ... after this edge (fast only)
  output wire                ovf_o,        // this axis carries
  output wire                can_o,        // active and non-zero integrand: can still carry
  output wire [AccWidth-1:0] jv_o,         // the integrand and the capacity (the pacer's
  output wire [AccWidth-1:0] cap_o         // norm operands)
);

  reg [AccWidth-1:0] jv_q  /* verilator public_flat_rd */;
  reg [AccWidth-1:0] jr_q  /* verilator public_flat_rd */;
  reg [AccWidth-1:0] cap_q /* verilator public_flat_rd */;
  assign jv_o  = jv_q;
  assign cap_o = cap_q;

  // The adder of the architectural registers (the probe `sum` of the register table).
  wire [AccWidth:0] sum /* verilator public_flat_rd */ = {1'b0, jr_q} + {1'b0, jv_q};

  // The registers that change only on a load.
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      jv_q  <= {AccWidth{1'b0}};
      cap_q <= {AccWidth{1'b0}};
    end else if (load_i) begin
      jv_q  <= jv_i;
      cap_q <= cap_i;
    end
  end

  if (Impl == "fast") begin : g_fast
    localparam integer EW = AccWidth + 1;
    reg [EW-1:0] e_q    /* verilator public_flat_rd */;
    reg [EW-1:0] jvmc_q /* verilator public_flat_rd */;
    reg          ovf_q  /* verilator public_flat_rd */;
    reg          jvz_q  /* verilator public_flat_rd */;

    // e = jr + jv - cap = jr + jv + ~cap + 1 at a load.
    wire [EW-1:0] e_ld;
    dda_add3 #(.Width(EW)) u_add_ld (.a_i({1'b0, jr_i}), .b_i({1'b0, jv_i}), .c_i(~{1'b0, cap_i}),
                                     .ci_i(1'b1), .s_o(e_ld));
    wire [EW-1:0] e_it;
    dda_add #(.Width(EW), .Split(EW / 2)) u_add_e (.a_i(e_q), .b_i(ovf_q ? jvmc_q : {1'b0, jv_q}), .s_o(e_it));
    wire [AccWidth-1:0] jr_it = ovf_q ? e_q[AccWidth-1:0] : sum[AccWidth-1:0];

    wire ovf_d = !rst_ni ? 1'b0 : load_i ? active_d_i & ~e_ld[EW-1]
               : iterate_i ? active_d_i & ~e_it[EW-1] : ovf_q;
    always @(posedge clk_i) begin
      ovf_q <= ovf_d;
      if (!rst_ni) begin
        jr_q   <= {AccWidth{1'b0}};
        e_q    <= {EW{1'b0}};
        jvmc_q <= {EW{1'b0}};
        jvz_q  <= 1'b1;
      end else if (load_i) begin
        jr_q   <= jr_i;
        e_q    <= e_ld;
        jvmc_q <= {1'b0, jv_i} - {1'b0, cap_i};
        jvz_q  <= jv_i == {AccWidth{1'b0}};
      end else if (iterate_i && active_i) begin
        jr_q <= jr_it;
        e_q  <= e_it;
      end
    end
    assign ovf_o = ovf_q;
    assign can_o = active_i & ~jvz_q;

`ifndef SYNTHESIS
    wire [EW-1:0] e_ref = {1'b0, jr_q} + {1'b0, jv_q} - {1'b0, cap_q};
    always @(posedge clk_i) begin
      if (rst_ni) begin
        `DDA_ASSERT(jvz_q == (jv_q == {AccWidth{1'b0}}), "ASSERTION dda_linear(fast): jvz_q differs from jv_q == 0")
        `DDA_ASSERT(jvmc_q == {1'b0, jv_q} - {1'b0, cap_q}, "ASSERTION dda_linear(fast): jvmc_q differs from jv_q - cap_q")
        `DDA_ASSERT(!active_i || e_q == e_ref, "ASSERTION dda_linear(fast): e_q differs from jr_q + jv_q - cap_q")
        `DDA_ASSERT(ovf_q == (active_i && sum >= {1'b0, cap_q}), "ASSERTION dda_linear(fast): ovf_q differs from the carry")
      end
    end
`endif
  end else begin : g_small
    // sum - cap_q: its carry out is the compare, its output the accumulator's next value.
    wire [AccWidth:0] jr_it;
    wire              ge;
    dda_addsel #(.Width(AccWidth + 1)) u_cmp (
      .a_i(sum), .b_i(~{1'b0, cap_q}), .ci_i(1'b1), .sel_i(ge), .s_o(jr_it), .co_o(ge)
    );
    assign ovf_o = active_i & ge;
    assign can_o = active_i & (jv_q != {AccWidth{1'b0}});
    always @(posedge clk_i) begin
      if (!rst_ni) begin
        jr_q <= {AccWidth{1'b0}};
      end else if (load_i) begin
        jr_q <= jr_i;
      end else if (iterate_i && active_i) begin
        jr_q <= jr_it[AccWidth-1:0];
      end
    end
    wire unused_small = &{1'b0, active_d_i, jr_it[AccWidth]};
  end

`ifndef SYNTHESIS
  // Both implementations: an active axis' accumulator stays below its capacity and its
  // integrand at most the capacity (the driver's guarantee).
  always @(posedge clk_i) begin
    if (rst_ni) begin
      `DDA_ASSERT(!active_i || (jr_q < cap_q && jv_q <= cap_q),
                  "ASSERTION dda_linear: an active axis needs jr_q < cap_q and jv_q <= cap_q")
    end
  end
`endif

endmodule
