// SPDX-License-Identifier: Apache-2.0
// One DDA integrator (docs/design.md, "Integrator"): integrand jv_q, accumulator jr_q
// and the two integrand corrections inc_on_x_q, inc_on_y_q, the architectural registers
// both implementations hold.
//
// Behaviour (both implementations): the carry ovf_o = add & (jr_q + jv_q >= cap_i),
// where add = active and the integrand is not negative (top bit clear). On an iteration
// (iterate_i) the accumulator keeps jr_q + jv_q - cap_i if it carried, jr_q + jv_q if it
// did not, and holds if the axis does not add; the integrand adds the corrections
// selected by both axes' carries of the same iteration, modulo 2^AccWidth.
//
// Impl (docs/design.md, "Implementations"):
//   "small"  computes the carry from the registers in the cycle it is used: the adder
//            jr_q + jv_q, its compare with the capacity and the integrand's correction
//            in series. Fewest registers; the SystemC model mirrors it.
//   "fast"   keeps the carry one edge ahead in registers of its own, derived from the
//            architectural ones (every one has an assertion saying what it equals):
//              e_q      = jr_q + jv_q - cap_q        (AccWidth + 1 bits, jv_q signed)
//              incmc_q  = inc_on_<own axis>_q - cap_q
//              incsum_q = inc_on_x_q + inc_on_y_q    (both signed, AccWidth + 1 bits)
//              add_q, ovf_q, jvz_q (jv_q == 0), and copies of the carries and of
//              add_q so that no flip-flop drives more than about a hundred LUTs
//            so the carry is a register, the control decides from registers only, and
//            each iteration is one carry chain per register behind a carry-save layer:
//              e' = e + (add ? jv : 0) + (ovf_x ? K_x : 0) + (ovf_y ? K_y : 0),
//            K_own = incmc, K_other = inc_on_<other axis>.
//            The e_q invariant needs the driver's guarantee that an active
//            integrand stays in [-cap, cap] and that no iteration wraps it around
//            2^AccWidth (docs/design.md; formal/dda_env.vh states it).
`include "dda_params.vh"
`include "dda_assert.vh"

module dda_integrator #(
  parameter integer AccWidth = `DDA_ACC_WIDTH,
  parameter         Impl     = "small",
  parameter integer IsY      = 0         // 1: the Y integrator (its "own" carry is Y; fast only)
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
  input  wire [AccWidth-1:0] cap_cmd_i,    // the command's capacity (fast: derived registers)
  // iterate (run, ce_i high, neither finished nor stalled)
  input  wire                iterate_i,
  input  wire [AccWidth-1:0] cap_i,        // shared capacity (dda_core.cap_q)
  input  wire                active_i,     // this axis' counter is non-zero
  input  wire                active_d_i,   // ... after this edge (fast only)
  input  wire                ovf_x_i,      // X carry of this iteration
  input  wire                ovf_y_i,      // Y carry of this iteration
  output wire                ovf_o,        // this integrator's carry
  output wire                ovf_d_o,      // ... after this edge (fast only)
  input  wire                ovf_x_d_i,    // both carries after this edge (fast only)
  input  wire                ovf_y_d_i,
  output wire                can_o,        // active and non-zero integrand: can still carry
  output wire [AccWidth-1:0] jv_o          // the integrand (the pacer's norm operand)
);

  reg [AccWidth-1:0] jv_q       /* verilator public_flat_rd */;
  assign jv_o = jv_q;
  reg [AccWidth-1:0] jr_q       /* verilator public_flat_rd */;
  reg [AccWidth-1:0] inc_on_x_q /* verilator public_flat_rd */;
  reg [AccWidth-1:0] inc_on_y_q /* verilator public_flat_rd */;

  // The adder of the architectural registers (the probe `sum` of the register table):
  // jr_q + jv_q < 2^(AccWidth + 1).
  wire [AccWidth:0] sum /* verilator public_flat_rd */ = {1'b0, jr_q} + {1'b0, jv_q};
  // A negative integrand (top bit set) holds its axis: no add, no carry.
  wire add = active_i & ~jv_q[AccWidth-1];

  // The registers that change only on a load: the corrections.
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      inc_on_x_q <= {AccWidth{1'b0}};
      inc_on_y_q <= {AccWidth{1'b0}};
    end else if (load_i) begin
      inc_on_x_q <= inc_on_x_i;
      inc_on_y_q <= inc_on_y_i;
    end
  end

  if (Impl == "fast") begin : g_fast
    localparam integer EW = AccWidth + 1;  // width of the derived sums
    reg [EW-1:0]       e_q      /* verilator public_flat_rd */;
    reg [EW-1:0]       incmc_q  /* verilator public_flat_rd */;
    reg [EW-1:0]       incsum_q /* verilator public_flat_rd */;
    reg                add_q    /* verilator public_flat_rd */;
    reg                ovf_q    /* verilator public_flat_rd */;
    reg                jvz_q    /* verilator public_flat_rd */;

    function automatic [EW-1:0] sx(input [AccWidth-1:0] v);
      sx = {v[AccWidth-1], v};
    endfunction

    // ---- the values a load writes (from the command word) ----
    wire [AccWidth-1:0] inc_own_i = (IsY != 0) ? inc_on_y_i : inc_on_x_i;
    // e = jr + jv - cap = jr + jv + ~cap + 1: one carry-save layer, one carry-select chain.
    wire [EW-1:0] e_ld;
    dda_add3 #(.Width(EW)) u_add_ld (.a_i({1'b0, jr_i}), .b_i(sx(jv_i)), .c_i(~{1'b0, cap_cmd_i}),
                                     .ci_i(1'b1), .s_o(e_ld));
    wire          add_ld = active_d_i & ~jv_i[AccWidth-1];

    // ---- one iteration ----
    // Copies of both carries for the two datapaths (each drives about a hundred LUTs;
    // ovf_q drives the control): registers of their own, loaded with the same next value.
    (* keep *) reg cw_x_q /* verilator public_flat_rd */;  // for the integrand's correction
    (* keep *) reg cw_y_q /* verilator public_flat_rd */;
    (* keep *) reg ce_x_q /* verilator public_flat_rd */;  // for e's carry-save layers
    (* keep *) reg ce_y_q /* verilator public_flat_rd */;
    (* keep *) reg ce_a_q /* verilator public_flat_rd */;  // a copy of add_q for them
    // The integrand's correction: one of 0, inc_on_x, inc_on_y, their sum (4:1 on the
    // carries), then one chain. The sum is AccWidth + 1 bits; jv_q keeps the low bits.
    wire [EW-1:0] w = cw_x_q ? (cw_y_q ? incsum_q : sx(inc_on_x_q))
                             : (cw_y_q ? sx(inc_on_y_q) : {EW{1'b0}});
    wire [EW-1:0] jv_it;
    dda_add #(.Width(EW), .Split(EW / 2)) u_add_jv (.a_i(sx(jv_q)), .b_i(w), .s_o(jv_it));
    // jv_q + w == 0 (mod 2^AccWidth) without the carry chain (dda_sum_zero).
    wire jvz_it;
    dda_sum_zero #(.Width(AccWidth)) u_jvz (.a_i(jv_q), .b_i(w[AccWidth-1:0]), .z_o(jvz_it));
    // e' = e + (add ? jv : 0) + (ovf_x ? K_x : 0) + (ovf_y ? K_y : 0): dda_add4.
    wire [EW-1:0] k_x = (IsY != 0) ? sx(inc_on_x_q) : incmc_q;
    wire [EW-1:0] k_y = (IsY != 0) ? incmc_q : sx(inc_on_y_q);
    wire [EW-1:0] t_a = e_q;
    wire [EW-1:0] t_b = {1'b0, ce_a_q ? jv_q : {AccWidth{1'b0}}};  // what the accumulator adds
    wire [EW-1:0] t_c = ce_x_q ? k_x : {EW{1'b0}};
    wire [EW-1:0] t_d = ce_y_q ? k_y : {EW{1'b0}};
    wire [EW-1:0] e_it;
    dda_add4 #(.Width(EW)) u_add_e (.a_i(t_a), .b_i(t_b), .c_i(t_c), .d_i(t_d), .s_o(e_it));
    wire [AccWidth-1:0] jr_it = ovf_q ? e_q[AccWidth-1:0] : sum[AccWidth-1:0];

    // The flags' next values, written so that the two late signals (the signs at the
    // ends of the chains) pass through one LUT: early terms are kept as nets of their own.
    (* keep *) wire jvt;  // the integrand's sign after the iteration
    assign jvt = jv_it[AccWidth-1];
    (* keep *) wire et;         // e's sign after the iteration
    assign et = e_it[EW-1];
    (* keep *) wire sel_it;
    assign sel_it = rst_ni & ~load_i & iterate_i;
    (* keep *) wire p_ovf;
    assign p_ovf = !rst_ni ? 1'b0 : load_i ? add_ld & ~e_ld[EW-1] : iterate_i ? active_d_i : ovf_q;
    (* keep *) wire p_add;
    assign p_add = !rst_ni ? 1'b0 : load_i ? add_ld : iterate_i ? active_d_i : add_q;
    wire ovf_d   = sel_it ? p_ovf & ~jvt & ~et : p_ovf;
    wire add_d   = sel_it ? p_add & ~jvt : p_add;
    assign ovf_d_o = ovf_d;
    always @(posedge clk_i) begin
      ce_a_q <= add_d;
      cw_x_q <= ovf_x_d_i;
      cw_y_q <= ovf_y_d_i;
      ce_x_q <= ovf_x_d_i;
      ce_y_q <= ovf_y_d_i;
    end

    assign ovf_o = ovf_q;
    assign can_o = add_q & ~jvz_q;

    always @(posedge clk_i) begin
      ovf_q <= ovf_d;
      add_q <= add_d;
      if (!rst_ni) begin
        jv_q     <= {AccWidth{1'b0}};
        jr_q     <= {AccWidth{1'b0}};
        e_q      <= {EW{1'b0}};
        incmc_q  <= {EW{1'b0}};
        incsum_q <= {EW{1'b0}};
        jvz_q    <= 1'b1;
      end else if (load_i) begin
        jv_q     <= jv_i;
        jr_q     <= jr_i;
        e_q      <= e_ld;
        incmc_q  <= sx(inc_own_i) - {1'b0, cap_cmd_i};
        incsum_q <= sx(inc_on_x_i) + sx(inc_on_y_i);
        jvz_q    <= jv_i == {AccWidth{1'b0}};
      end else if (iterate_i) begin
        jv_q     <= jv_it[AccWidth-1:0];
        if (add_q) jr_q <= jr_it;
        e_q      <= e_it;
        jvz_q    <= jvz_it;
      end
    end

`ifndef SYNTHESIS
    // The derived registers equal what they are derived from (the e_q one
    // while the axis is active: the driver's integrand range holds for active axes).
    wire [EW-1:0] e_ref = {1'b0, jr_q} + sx(jv_q) - {1'b0, cap_i};
    wire [EW-1:0] cap_x = {1'b0, cap_i};
    always @(posedge clk_i) begin
      if (rst_ni) begin
        `DDA_ASSERT(add_q == add, "ASSERTION dda_integrator(fast): add_q differs from active & jv_q >= 0")
        `DDA_ASSERT(jvz_q == (jv_q == {AccWidth{1'b0}}), "ASSERTION dda_integrator(fast): jvz_q differs from jv_q == 0")
        `DDA_ASSERT(ce_a_q == add_q, "ASSERTION dda_integrator(fast): the copy of add_q differs from it")
        `DDA_ASSERT(incmc_q == sx((IsY != 0) ? inc_on_y_q : inc_on_x_q) - cap_x,
                    "ASSERTION dda_integrator(fast): incmc_q differs from inc_on_own_q - cap_q")
        `DDA_ASSERT(incsum_q == sx(inc_on_x_q) + sx(inc_on_y_q),
                    "ASSERTION dda_integrator(fast): incsum_q differs from inc_on_x_q + inc_on_y_q")
        `DDA_ASSERT(!active_i || e_q == e_ref, "ASSERTION dda_integrator(fast): e_q differs from jr_q + jv_q - cap_q")
        `DDA_ASSERT(ovf_q == (add && sum >= cap_x), "ASSERTION dda_integrator(fast): ovf_q differs from the carry")
        `DDA_ASSERT(cw_x_q == ovf_x_i && ce_x_q == ovf_x_i, "ASSERTION dda_integrator(fast): a copy of the X carry differs from it")
        `DDA_ASSERT(cw_y_q == ovf_y_i && ce_y_q == ovf_y_i, "ASSERTION dda_integrator(fast): a copy of the Y carry differs from it")
      end
    end
`endif
  end else begin : g_small
    // Three carry chains, each bit one logic cell on iCE40 (dda_addsel): the adder
    // `sum`, then sum - cap_i whose carry out is the compare (ge = sum >= cap_i) and
    // whose output is already the accumulator's next value (sum - cap_i if ge, sum if
    // not), then the integrand's two corrections, one chain each, the carries choosing
    // their outputs.
    wire [AccWidth:0] jr_it;
    wire              ge;
    dda_addsel #(.Width(AccWidth + 1)) u_cmp (
      .a_i(sum), .b_i(~{1'b0, cap_i}), .ci_i(1'b1), .sel_i(ge), .s_o(jr_it), .co_o(ge)
    );
    wire ovf = add & ge;
    wire [AccWidth-1:0] jv_x, jv_it;
    wire                unused_co_x, unused_co_y;
    dda_addsel #(.Width(AccWidth)) u_corr_x (
      .a_i(jv_q), .b_i(inc_on_x_q), .ci_i(1'b0), .sel_i(ovf_x_i), .s_o(jv_x), .co_o(unused_co_x)
    );
    dda_addsel #(.Width(AccWidth)) u_corr_y (
      .a_i(jv_x), .b_i(inc_on_y_q), .ci_i(1'b0), .sel_i(ovf_y_i), .s_o(jv_it), .co_o(unused_co_y)
    );
    assign ovf_o = ovf;
    assign can_o = add & (jv_q != {AccWidth{1'b0}});

    always @(posedge clk_i) begin
      if (!rst_ni) begin
        jv_q <= {AccWidth{1'b0}};
        jr_q <= {AccWidth{1'b0}};
      end else if (load_i) begin
        jv_q <= jv_i;
        jr_q <= jr_i;
      end else if (iterate_i) begin
        if (add) jr_q <= jr_it[AccWidth-1:0];
        jv_q <= jv_it;
      end
    end

    assign ovf_d_o = 1'b0;
    wire unused_small = &{1'b0, cap_cmd_i, active_d_i, ovf_x_d_i, ovf_y_d_i, jr_it[AccWidth],
                          unused_co_x, unused_co_y};
  end

`ifndef SYNTHESIS
  // Both implementations (rtl/dda_assert.vh): the accumulator stays below the capacity
  // (both 0 after reset); it needs the driver's integrand range (docs/design.md).
  always @(posedge clk_i) begin
    if (rst_ni) begin
      `DDA_ASSERT(jr_q < cap_i || (jr_q == {AccWidth{1'b0}} && cap_i == {AccWidth{1'b0}}),
                  "ASSERTION dda_integrator: the accumulator is not below the capacity")
    end
  end
`endif

endmodule
