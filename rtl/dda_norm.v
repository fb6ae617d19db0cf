// SPDX-License-Identifier: Apache-2.0
// The pacer's norm unit (docs/design.md, "Pacer"; reference: motion::iteration_distance
// in model/motion/pacer.hpp): the DDA's path length per iteration,
//   q_i = floor(v_i * 2^NF / cap_i) for the axes x, y, z (v_i = 0 for an inactive axis),
//   d   = floor(sqrt(q_x^2 + q_y^2 + q_z^2)),
// exactly, in Latency (56 at NF 20) edges after the edge that starts it, with one
// restoring divider and one shift-add squarer serving the three axes in turn and a
// digit-by-digit square root, each two bits per clock (two radix-2 steps in a row: the
// adders stay the width they were, only their number doubles). An integrand is at most
// its capacity (a DDA axis steps at most once per iteration), so each q has NF + 1 = QW
// bits and d at most NF + 2.
//
// Each unit takes QC = ceil(QW / 2) clocks. The divider makes 2 QC quotient bits,
// floor(v * 2^(2 QC - 1) / cap), of which q drops the last 2 QC - QW; the root takes
// its 2 QC bits from the sum zero-extended to 4 QC bits, so its first 2 QC - QW are 0.
//
// Schedule: start_i on edge E (the operands may still change on it: a command loaded on
// E). The divider takes x's operands from the inputs on E + 1 and divides on E + 1 ..
// E + QC, y's (read on E + QC + 1) on the next QC edges, z's on the QC after; the squarer
// squares each quotient on the QC edges after its division, adding every square into one
// sum (so x's squaring runs beside y's division); E + 4 QC + 1 takes the sum, E + 4 QC + 2
// .. E + 5 QC + 1 take the root's bits: d_o holds the result from E + Latency until the
// next one. A start while busy starts again; the operands must hold until E + 2 QC + 1
// (OperandEdges after the start), the edge that reads z's.
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

  localparam integer QW = NF + 1;         // a quotient
  localparam integer QC = (QW + 1) / 2;   // the clocks of each unit: two bits a clock
  localparam integer QB = 2 * QC;         // the divider's quotient bits (q drops QB - QW)
  localparam integer SW = 2 * QW;         // a square, and the sum of three (each at most 2^(2 NF))
  localparam integer RW = 4 * QC;         // the radicand: the sum zero-extended
  localparam integer DivEnd = 3 * QC;     // the last dividing clock (z's)
  localparam integer SqEnd  = 4 * QC;     // the last squaring clock
  localparam integer Sum    = 4 * QC + 1;
  localparam integer Last   = 5 * QC + 1; // the last root clock: Latency, 56 at NF 20

  reg [6:0]    cyc_q  /* verilator public_flat_rd */;  // 0: idle, else the clock of this edge
  reg [AW:0]   r_q    /* verilator public_flat_rd */;  // the divider's remainder
  reg [AW-1:0] c_q    /* verilator public_flat_rd */;  // its divisor
  reg [QB-1:0] q_q    /* verilator public_flat_rd */;  // its quotient
  reg [QW-1:0] sq_q   /* verilator public_flat_rd */;  // the squarer's multiplier, shifting down
  reg [SW-1:0] mc_q   /* verilator public_flat_rd */;  // its multiplicand, shifting up
  reg [SW-1:0] a_q    /* verilator public_flat_rd */;  // the sum of the squares
  reg [RW-1:0] s_q    /* verilator public_flat_rd */;  // the radicand, shifted out four bits a clock
  reg [QW:0]   rem_q  /* verilator public_flat_rd */;  // the root's remainder, at most twice the root
  reg [QW-1:0] root_q /* verilator public_flat_rd */;  // the root's bits so far
  reg [NF+1:0] d_q    /* verilator public_flat_rd */;

  // The axis' first dividing clock and first squaring clock.
  wire div_x  = cyc_q == 7'd1;
  wire div_y  = cyc_q == 7'(QC + 1);
  wire div_z  = cyc_q == 7'(2 * QC + 1);
  wire first  = div_x | div_y | div_z;
  wire div    = cyc_q != 7'd0 && cyc_q <= 7'(DivEnd);
  wire sq0    = cyc_q == 7'(QC + 1) || cyc_q == 7'(2 * QC + 1) || cyc_q == 7'(3 * QC + 1);
  wire sq     = cyc_q > 7'(QC) && cyc_q <= 7'(SqEnd);
  wire root   = cyc_q > 7'(Sum);

  // Two dividing steps: the remainder (the dividend itself on an axis' first) against
  // the divisor; each a quotient bit, and the remainder doubled for the next step.
  wire [AW-1:0] v   = div_x ? v_x_i : div_y ? v_y_i : v_z_i;
  wire [AW:0]   n1  = first ? {1'b0, v} : r_q;
  wire [AW-1:0] dv  = first ? (div_z ? cap_z_i : cap_i) : c_q;
  wire [AW+1:0] t1  = {1'b0, n1} - {2'b0, dv};
  wire          b1  = ~t1[AW+1];
  wire [AW:0]   k1  = b1 ? t1[AW:0] : n1;
  // (a remainder is below its divisor, so the doubled one fits AW + 1 bits)
  wire [AW:0]   n2  = {k1[AW-1:0], 1'b0};
  wire [AW+1:0] t2  = {1'b0, n2} - {2'b0, dv};
  wire          b2  = ~t2[AW+1];
  wire [AW:0]   k2  = b2 ? t2[AW:0] : n2;
  wire          unused_k = &{1'b0, k1[AW], k2[AW]};

  // Two squaring steps: a += multiplier[0] ? multiplicand : 0, and multiplier[1] ? twice
  // it : 0; on an axis' first, the quotient just finished is both (the divider's q_q,
  // which its next axis then fills).
  wire [QW-1:0] qv   = q_q[QB-1 -: QW];
  wire [QW-1:0] mul  = sq0 ? qv : sq_q;
  wire [SW-1:0] mcd  = sq0 ? SW'(qv) : mc_q;
  wire [SW-1:0] add0 = mul[0] ? mcd : '0;
  wire [SW-1:0] add1 = mul[1] ? {mcd[SW-2:0], 1'b0} : '0;
  wire          unused_q = &{1'b0, q_q[QB-QW-1:0]};

  // Two root steps: each the radicand's next two bits into the remainder, against
  // 4 root + 1.
  wire [QW+2:0] rn1  = {rem_q, s_q[RW-1:RW-2]};
  wire [QW+3:0] rt1  = {1'b0, rn1} - {2'b0, root_q, 2'b01};
  wire          rb1  = ~rt1[QW+3];
  wire [QW:0]   rm1  = rb1 ? rt1[QW:0] : rn1[QW:0];
  wire [QW-1:0] ro1  = {root_q[QW-2:0], rb1};
  wire [QW+2:0] rn2  = {rm1, s_q[RW-3:RW-4]};
  wire [QW+3:0] rt2  = {1'b0, rn2} - {2'b0, ro1, 2'b01};
  wire          rb2  = ~rt2[QW+3];

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
        r_q <= {k2[AW-1:0], 1'b0};
        q_q <= {q_q[QB-3:0], b1, b2};
        if (first) c_q <= dv;
      end
      if (sq) begin
        a_q  <= (cyc_q == 7'(QC + 1) ? '0 : a_q) + add0 + add1;
        mc_q <= {mcd[SW-3:0], 2'b00};
        sq_q <= mul >> 2;
      end
      if (cyc_q == 7'(Sum)) begin
        s_q    <= RW'(a_q);
        rem_q  <= '0;
        root_q <= '0;
      end
      if (root) begin
        rem_q  <= rb2 ? rt2[QW:0] : rn2[QW:0];
        root_q <= {ro1[QW-2:0], rb2};
        s_q    <= s_q << 4;
        if (cyc_q == 7'(Last)) d_q <= (NF+2)'({ro1[QW-2:0], rb2});
      end
    end
  end

  assign busy_o = start_i | (cyc_q != 7'd0);
  assign d_o    = d_q;

endmodule
