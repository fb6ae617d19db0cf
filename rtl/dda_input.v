// SPDX-License-Identifier: Apache-2.0
// One machine input of the motion block (docs/design.md, "Machine inputs"): the pin,
// inverted to its active-high sense, through a two-flip-flop synchronizer (s1_q, s2_q)
// and a glitch filter. The filtered level lvl_q takes the synchronized level once that
// has differed from it on filter_i ticks (tick_i high; 0 counts as 1) without a break:
// the count holds between ticks and starts again whenever the two agree. With a tick on
// every clock (the probe's), a pulse shorter than filter_i clocks never reaches lvl_q and
// a pin that changes before edge 0 shows in it after edge 1 + max(filter_i, 1); with a
// tick every P clocks (the switches', P = 2^IN_FILTER.tick), a pulse shorter than
// (filter_i - 1) P + 1 clocks never does and a level held filter_i P clocks always does.
// rise_o marks the edge lvl_q turns active on. The pin may change at any time: only
// s1_q samples it.
module dda_input #(
  parameter integer FW = 16
) (
  input  wire          clk_i,
  input  wire          rst_ni,
  input  wire          pin_i,
  input  wire          invert_i,  // the pin is active low
  input  wire          tick_i,    // the filter counts on this edge
  input  wire [FW-1:0] filter_i,
  output wire          level_o,   // the filtered level, 1: active
  output wire          rise_o     // it turns active on this edge
);

  reg          s1_q  /* verilator public_flat_rd */;
  reg          s2_q  /* verilator public_flat_rd */;
  reg          lvl_q /* verilator public_flat_rd */;
  reg [FW-1:0] cnt_q /* verilator public_flat_rd */;  // ticks s2_q has differed from lvl_q

  wire          differ  = s2_q != lvl_q;
  wire [FW-1:0] cnt_inc = cnt_q + FW'(1);  // at most filter_i: no wrap
  wire          flip    = differ & tick_i & (cnt_inc >= filter_i);

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      s1_q  <= 1'b0;
      s2_q  <= 1'b0;
      lvl_q <= 1'b0;
      cnt_q <= '0;
    end else begin
      s1_q  <= pin_i ^ invert_i;
      s2_q  <= s1_q;
      lvl_q <= lvl_q ^ flip;
      if (!differ || flip) cnt_q <= '0;
      else if (tick_i) cnt_q <= cnt_inc;
    end
  end

  assign level_o = lvl_q;
  assign rise_o  = flip & s2_q;

endmodule
