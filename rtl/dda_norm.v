// SPDX-License-Identifier: Apache-2.0
// The pacer's norm unit (docs/design.md, "Pacer"; reference: motion::iteration_distance
// in model/motion/pacer.hpp): the DDA's path length per iteration,
//   q_i = floor(v_i * 2^NF / cap_i) for the axes x, y, z (v_i = 0 for an inactive axis),
//   d   = floor(sqrt(q_x^2 + q_y^2 + q_z^2)),
// exactly, in Latency (64) edges after the edge that starts it, with three restoring
// dividers, three shift-add squarers and a digit-by-digit square root, each a bit per
// clock. An integrand is at most its capacity (a DDA axis steps at most once per
// iteration), so each q has NF + 1 bits and d at most NF + 2.
//
// Schedule: start_i on edge E (the operands may still change on it: a command loaded on
// E); edge E + 1 takes the operands from the inputs and runs the dividers' first step;
// E + 1 .. E + 21 divide, E + 22 .. E + 42 square, E + 43 adds the squares, E + 44 ..
// E + 64 take the root's bits; d_o holds the result from E + 64 until the next one.
// A start while busy starts again.
`include "dda_params.vh"

// Instantiated by the pacer (rtl/dda_pace.v), which is not yet in the block: a top of its
// own beside dda_motion when rtl/*.v is linted together.
/* verilator lint_off MULTITOP */
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
  localparam integer SW = 2 * QW;       // a square
  localparam integer DivEnd = QW;       // the last dividing step
  localparam integer SqEnd  = 2 * QW;   // the last squaring step
  localparam integer Sum    = 2 * QW + 1;
  localparam integer Last   = 3 * QW + 1;  // the last root step: 64 at NF 20

  reg [6:0]    cyc_q /* verilator public_flat_rd */;  // 0: idle, else the step of this edge
  // dividing: the remainder; squaring: the multiplicand, shifted up
  reg [AW:0]   r_x_q /* verilator public_flat_rd */, r_y_q /* verilator public_flat_rd */,
               r_z_q /* verilator public_flat_rd */;
  reg [AW-1:0] c_x_q /* verilator public_flat_rd */, c_z_q /* verilator public_flat_rd */;  // the divisors (x's serves y)
  // dividing: the quotient; squaring: its bits, shifted out
  reg [QW-1:0] q_x_q /* verilator public_flat_rd */, q_y_q /* verilator public_flat_rd */,
               q_z_q /* verilator public_flat_rd */;
  reg [SW-1:0] a_x_q /* verilator public_flat_rd */, a_y_q /* verilator public_flat_rd */,
               a_z_q /* verilator public_flat_rd */;  // the squares
  reg [SW+1:0] s_q /* verilator public_flat_rd */;     // their sum (< 2^SW), shifted out two bits per root step
  reg [QW:0]   rem_q /* verilator public_flat_rd */;   // the root's remainder, at most twice the root
  reg [QW-1:0] root_q /* verilator public_flat_rd */;  // the root's bits so far
  reg [NF+1:0] d_q /* verilator public_flat_rd */;

  wire first = cyc_q == 7'd1;
  wire div   = cyc_q != 7'd0 && cyc_q <= 7'(DivEnd);
  wire sq    = cyc_q > 7'(DivEnd) && cyc_q <= 7'(SqEnd);
  wire sq0   = cyc_q == 7'(DivEnd + 1);
  wire root  = cyc_q > 7'(Sum);

  // One dividing step: the remainder (the dividend itself on the first) against the
  // divisor; the quotient bit, and the remainder doubled for the next step.
  wire [AW:0]   n_x = first ? {1'b0, v_x_i} : r_x_q;
  wire [AW:0]   n_y = first ? {1'b0, v_y_i} : r_y_q;
  wire [AW:0]   n_z = first ? {1'b0, v_z_i} : r_z_q;
  wire [AW-1:0] d_x = first ? cap_i : c_x_q;
  wire [AW-1:0] d_z = first ? cap_z_i : c_z_q;
  wire [AW+1:0] t_x = {1'b0, n_x} - {2'b0, d_x};
  wire [AW+1:0] t_y = {1'b0, n_y} - {2'b0, d_x};
  wire [AW+1:0] t_z = {1'b0, n_z} - {2'b0, d_z};
  wire          b_x = ~t_x[AW+1];
  wire          b_y = ~t_y[AW+1];
  wire          b_z = ~t_z[AW+1];
  wire [AW:0]   k_x = b_x ? t_x[AW:0] : n_x;
  wire [AW:0]   k_y = b_y ? t_y[AW:0] : n_y;
  wire [AW:0]   k_z = b_z ? t_z[AW:0] : n_z;
  wire          unused_k = &{1'b0, k_x[AW], k_y[AW], k_z[AW]};  // a remainder is below its divisor

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
        r_x_q <= {k_x[AW-1:0], 1'b0};
        r_y_q <= {k_y[AW-1:0], 1'b0};
        r_z_q <= {k_z[AW-1:0], 1'b0};
        q_x_q <= {q_x_q[QW-2:0], b_x};
        q_y_q <= {q_y_q[QW-2:0], b_y};
        q_z_q <= {q_z_q[QW-2:0], b_z};
        if (first) begin
          c_x_q <= cap_i;
          c_z_q <= cap_z_i;
        end
      end
      if (sq) begin
        // a += q[0] ? q << i : 0, the multiplicand shifting up in r, the multiplier down in q.
        a_x_q <= (sq0 ? '0 : a_x_q) + (q_x_q[0] ? (sq0 ? SW'(q_x_q) : SW'(r_x_q)) : '0);
        a_y_q <= (sq0 ? '0 : a_y_q) + (q_y_q[0] ? (sq0 ? SW'(q_y_q) : SW'(r_y_q)) : '0);
        a_z_q <= (sq0 ? '0 : a_z_q) + (q_z_q[0] ? (sq0 ? SW'(q_z_q) : SW'(r_z_q)) : '0);
        r_x_q <= (sq0 ? (AW+1)'(q_x_q) : r_x_q) << 1;
        r_y_q <= (sq0 ? (AW+1)'(q_y_q) : r_y_q) << 1;
        r_z_q <= (sq0 ? (AW+1)'(q_z_q) : r_z_q) << 1;
        q_x_q <= q_x_q >> 1;
        q_y_q <= q_y_q >> 1;
        q_z_q <= q_z_q >> 1;
      end
      if (cyc_q == 7'(Sum)) begin
        s_q    <= {a_x_q + a_y_q + a_z_q, 2'b00};  // (each square at most 2^(2 NF), the sum below 2^SW)
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
/* verilator lint_on MULTITOP */
