// SPDX-License-Identifier: Apache-2.0
// The reference core for the formal equivalence proofs (scripts/formal.sh): dda_core as
// it was before the fast and small implementations (commit 7e45f85), modules
// renamed with a _ref suffix. Not part of the IP; do not edit: the proofs show that
// rtl/dda_core.v (each Impl) is equal to this at the ports, edge by edge.
// Remaining-step counter of one axis (docs/design.md, "Counter"): cnt_q, decremented by
// the axis' carry on an iteration. active_o = cnt_q != 0 (an axis whose counter is 0
// stops adding); last_o says the counter is 0 after this iteration.
`include "dda_params.vh"
`include "dda_assert.vh"

module dda_counter_ref #(
  parameter integer CntWidth = `DDA_CNT_WIDTH
) (
  input  wire                clk_i,
  input  wire                rst_ni,    // synchronous, active low
  input  wire                load_i,    // load cnt_i (cmd_valid_i && cmd_ready_o; wins over iterate_i)
  input  wire [CntWidth-1:0] cnt_i,
  input  wire                iterate_i, // an iteration happens on this edge
  input  wire                dec_i,     // this axis carried in this iteration
  output wire                active_o,
  output wire                last_o
);

  reg [CntWidth-1:0] cnt_q /* verilator public_flat_rd */;
  reg [CntWidth-1:0] cnt_d;

  wire [CntWidth-1:0] dec = {{(CntWidth-1){1'b0}}, dec_i};

  assign active_o = cnt_q != {CntWidth{1'b0}};
  assign last_o   = cnt_q == dec;  // cnt_q - dec_i == 0

  always @(*) begin
    cnt_d = cnt_q;
    if (load_i) begin
      cnt_d = cnt_i;
    end else if (iterate_i) begin
      cnt_d = cnt_q - dec;
    end
  end

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      cnt_q <= {CntWidth{1'b0}};
    end else begin
      cnt_q <= cnt_d;
    end
  end

`ifndef SYNTHESIS
  // Assertion (rtl/dda_assert.vh): a counter at 0 never decrements: it stays at 0
  // until a load.
  always @(posedge clk_i) begin
    if (rst_ni) begin
      `DDA_ASSERT(load_i || cnt_q != {CntWidth{1'b0}} || cnt_d == {CntWidth{1'b0}},
                  "ASSERTION dda_counter_ref: a decrement at 0")
    end
  end
`endif

endmodule
