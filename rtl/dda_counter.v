// SPDX-License-Identifier: Apache-2.0
// Remaining-step counter of one axis (docs/design.md, "Counter"): cnt_q, decremented by
// the axis' carry on an iteration. active_o = cnt_q != 0 (an axis whose counter is 0
// stops adding); last_o says the counter is 0 after this iteration; active_d_o is
// active_o after this edge.
//
// Impl "small" compares cnt_q in the cycle; "fast" keeps nz_q = (cnt_q != 0) and
// one_q = (cnt_q == 1) in registers of its own, so the control reads flip-flops.
`include "dda_params.vh"
`include "dda_assert.vh"

module dda_counter #(
  parameter integer CntWidth = `DDA_CNT_WIDTH,
  parameter         Impl     = "small"
) (
  input  wire                clk_i,
  input  wire                rst_ni,    // synchronous, active low
  input  wire                load_i,    // load cnt_i (cmd_valid_i && cmd_ready_o; wins over iterate_i)
  input  wire [CntWidth-1:0] cnt_i,
  input  wire                iterate_i, // an iteration happens on this edge
  input  wire                dec_i,     // this axis carried in this iteration
  output wire                active_o,
  output wire                active_d_o,
  output wire                last_o
);

  reg [CntWidth-1:0] cnt_q /* verilator public_flat_rd */;
  reg [CntWidth-1:0] cnt_d;

  wire [CntWidth-1:0] dec = {{(CntWidth-1){1'b0}}, dec_i};

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

  if (Impl == "fast") begin : g_fast
    reg nz_q  /* verilator public_flat_rd */;
    reg one_q /* verilator public_flat_rd */;
    localparam [CntWidth-1:0] One = {{(CntWidth-1){1'b0}}, 1'b1};
    localparam [CntWidth-1:0] Two = {{(CntWidth-2){1'b0}}, 2'b10};
    reg nz_d, one_d;
    always @(*) begin
      nz_d  = nz_q;
      one_d = one_q;
      if (load_i) begin
        nz_d  = cnt_i != {CntWidth{1'b0}};
        one_d = cnt_i == One;
      end else if (iterate_i && dec_i) begin
        nz_d  = ~one_q;
        one_d = cnt_q == Two;
      end
    end
    always @(posedge clk_i) begin
      if (!rst_ni) begin
        nz_q  <= 1'b0;
        one_q <= 1'b0;
      end else begin
        nz_q  <= nz_d;
        one_q <= one_d;
      end
    end
    assign active_o   = nz_q;
    assign active_d_o = nz_d;
    assign last_o     = dec_i ? one_q : ~nz_q;
`ifndef SYNTHESIS
    always @(posedge clk_i) begin
      if (rst_ni) begin
        `DDA_ASSERT(nz_q == (cnt_q != {CntWidth{1'b0}}), "ASSERTION dda_counter(fast): nz_q differs from cnt_q != 0")
        `DDA_ASSERT(one_q == (cnt_q == One), "ASSERTION dda_counter(fast): one_q differs from cnt_q == 1")
      end
    end
`endif
  end else begin : g_small
    assign active_o   = cnt_q != {CntWidth{1'b0}};
    assign active_d_o = cnt_d != {CntWidth{1'b0}};
    assign last_o     = cnt_q == dec;  // cnt_q - dec_i == 0
  end

`ifndef SYNTHESIS
  // Assertion (rtl/dda_assert.vh): a counter at 0 never decrements: it stays at 0
  // until a load.
  always @(posedge clk_i) begin
    if (rst_ni) begin
      `DDA_ASSERT(load_i || cnt_q != {CntWidth{1'b0}} || cnt_d == {CntWidth{1'b0}},
                  "ASSERTION dda_counter: a decrement at 0")
    end
  end
`endif

endmodule
