// SPDX-License-Identifier: Apache-2.0
// The pacer's norm unit (docs/design.md, "Pacer"; reference: motion::iteration_distance
// in model/motion/pacer.hpp): the DDA's path length per iteration,
//   q_i = floor(v_i * 2^NF / cap_i) for the axes x, y, z (v_i = 0 for an inactive axis),
//   d   = floor(sqrt(q_x^2 + q_y^2 + q_z^2)),
// exactly, in Latency (106) edges after the edge that starts it, with one restoring
// divider and one shift-add squarer serving the three axes in turn and a digit-by-digit
// square root, each a bit per clock. An integrand is at most its capacity (a DDA axis
// steps at most once per iteration), so each q has NF + 1 = QW bits and d at most NF + 2.
//
// Schedule: start_i on edge E (the operands may still change on it: a command loaded on
// E). The divider takes x's operands from the inputs on E + 1 and divides on E + 1 ..
// E + QW, y's (read on E + QW + 1) on the next QW edges, z's on the QW after; the squarer
// squares each quotient on the QW edges after its division, adding every square into one
// sum (so x's squaring runs beside y's division); E + 4 QW + 1 takes the sum, E + 4 QW + 2
// .. E + 5 QW + 1 take the root's bits: d_o holds the result from E + 106 (NF 20) until
// the next one. A start while busy starts again; the operands must hold until E + 2 QW + 1.
`include "dda_params.vh"

// Instantiated by the pacer (rtl/dda_pace.v).
module dda_norm #(
  parameter integer AW = `DDA_ACC_WIDTH,  // the integrands' and capacities' width
  parameter integer NF = 20   // fraction bits of q and d
) (
  input  wire          clk_i,
  input  wire          rst_ni,    // synchronous, active low
  input  wire          start_i,
  input  wire [AW-1:0] v_x_i,     // the axes' integrands (0: inactive), at most their capacity
  input  wire [AW-1:0] v_y_i,
  input  wire [AW-1:0] v_z_i,
  input  wire [AW-1:0] cap_i,     // x's and y's capacity
  input  wire [AW-1:0] cap_z_i,
  output wire          busy_o,
  output wire [NF+1:0] d_o
);

  localparam integer QW = NF + 1;       // a quotient
  localparam integer SW = 2 * QW;       // a square, and the sum of three (each at most 2^(2 NF))
  localparam integer DivEnd = 3 * QW;   // the last dividing step (z's)
  localparam integer SqEnd  = 4 * QW;   // the last squaring step
  localparam integer Sum    = 4 * QW + 1;
  localparam integer Last   = 5 * QW + 1;  // the last root step: 106 at NF 20

  reg [6:0]    cyc_q  /* verilator public_flat_rd */;  // 0: idle, else the step of this edge
  reg [AW:0]   r_q    /* verilator public_flat_rd */;  // the divider's remainder
  reg [AW-1:0] c_q    /* verilator public_flat_rd */;  // its divisor
  reg [QW-1:0] q_q    /* verilator public_flat_rd */;  // its quotient
  reg [QW-1:0] sq_q   /* verilator public_flat_rd */;  // the squarer's multiplier, shifting down
  reg [SW-1:0] mc_q   /* verilator public_flat_rd */;  // its multiplicand, shifting up
  reg [SW-1:0] a_q    /* verilator public_flat_rd */;  // the sum of the squares
  reg [SW+1:0] s_q    /* verilator public_flat_rd */;  // the sum, shifted out two bits per root step
  reg [QW:0]   rem_q  /* verilator public_flat_rd */;  // the root's remainder, at most twice the root
  reg [QW-1:0] root_q /* verilator public_flat_rd */;  // the root's bits so far
  reg [NF+1:0] d_q    /* verilator public_flat_rd */;

  // The axis' first dividing step and first squaring step.
  wire div_x  = cyc_q == 7'd1;
  wire div_y  = cyc_q == 7'(QW + 1);
  wire div_z  = cyc_q == 7'(2 * QW + 1);
  wire first  = div_x | div_y | div_z;
  wire div    = cyc_q != 7'd0 && cyc_q <= 7'(DivEnd);
  wire sq0    = cyc_q == 7'(QW + 1) || cyc_q == 7'(2 * QW + 1) || cyc_q == 7'(3 * QW + 1);
  wire sq     = cyc_q > 7'(QW) && cyc_q <= 7'(SqEnd);
  wire root   = cyc_q > 7'(Sum);

  // One dividing step: the remainder (the dividend itself on the first) against the
  // divisor; the quotient bit, and the remainder doubled for the next step.
  wire [AW-1:0] v   = div_x ? v_x_i : div_y ? v_y_i : v_z_i;
  wire [AW:0]   n   = first ? {1'b0, v} : r_q;
  wire [AW-1:0] dv  = first ? (div_z ? cap_z_i : cap_i) : c_q;
  wire [AW+1:0] t   = {1'b0, n} - {2'b0, dv};
  wire          b   = ~t[AW+1];
  wire [AW:0]   k   = b ? t[AW:0] : n;
  wire          unused_k = &{1'b0, k[AW]};  // a remainder is below its divisor

  // One squaring step: a += multiplier[0] ? multiplicand : 0; on an axis' first, the
  // quotient just finished is both (the divider's q_q, which its next axis then fills).
  wire [QW-1:0] mul  = sq0 ? q_q : sq_q;
  wire [SW-1:0] mcd  = sq0 ? SW'(q_q) : mc_q;

  // One root step: the next two bits of the sum into the remainder, against 4 root + 1.
  wire [QW+2:0] rn   = {rem_q, s_q[SW+1:SW]};
  wire [QW+3:0] rt   = {1'b0, rn} - {2'b0, root_q, 2'b01};
  wire          rbit = ~rt[QW+3];

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      cyc_q  <= 7'd0;
      d_q    <= '0;
    end else if (start_i) begin
      cyc_q  <= 7'd1;
    end else if (cyc_q != 7'd0) begin
      cyc_q <= cyc_q == 7'(Last) ? 7'd0 : cyc_q + 7'd1;
    end
    if (rst_ni && !start_i) begin
      if (div) begin
        // (the doubled remainder is below twice the divisor: it fits AW + 1 bits)
        r_q <= {k[AW-1:0], 1'b0};
        q_q <= {q_q[QW-2:0], b};
        if (first) c_q <= dv;
      end
      if (sq) begin
        a_q  <= (cyc_q == 7'(QW + 1) ? '0 : a_q) + (mul[0] ? mcd : '0);
        mc_q <= mcd << 1;
        sq_q <= mul >> 1;
      end
      if (cyc_q == 7'(Sum)) begin
        s_q    <= {a_q, 2'b00};
        rem_q  <= '0;
        root_q <= '0;
      end
      if (root) begin
        rem_q  <= rbit ? rt[QW:0] : rn[QW:0];
        root_q <= {root_q[QW-2:0], rbit};
        s_q    <= s_q << 2;
        if (cyc_q == 7'(Last)) d_q <= {root_q, rbit};
      end
    end
  end

  assign busy_o = start_i | (cyc_q != 7'd0);
  assign d_o    = d_q;

endmodule
