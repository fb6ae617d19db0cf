// SPDX-License-Identifier: Apache-2.0
// The step/dir stage of one axis of the motion block (docs/design.md, "Step and direction
// timing"): turns the core's one-cycle step pulses into pulses a drive accepts, with
// hostmot2's four timings in clock cycles (TW-bit fields of the block's STEP_*/DIR_*
// registers):
//   steplen   the step output is high for max(steplen, 1) cycles;
//   stepspace it is low for at least max(stepspace, 1) cycles between two pulses;
//   dirsetup  the direction output is stable for at least dirsetup cycles before a rising
//             step edge (0: it may change on the rising edge itself);
//   dirhold   and for at least dirhold cycles after a falling one (0: it may change on the
//             falling edge itself).
// A core step waits in a one-step buffer (pend_q, with its direction) until the timings
// let it out; hold_o asks the block to stop the core while the buffer is (or is about to
// be) full, so no step is dropped, merged or reordered. rise_o marks the edge on which a
// pulse starts (the block counts the position there, in the direction dir_d). flush_i
// (abort) empties the buffer; a pulse already out finishes its steplen.
`include "dda_assert.vh"

module dda_stepdir #(
  parameter integer TW = 12
) (
  input  wire          clk_i,
  input  wire          rst_ni,
  input  wire          flush_i,
  input  wire          step_i,      // the core's step pulse (registered in the core)
  input  wire          dir_i,       // its direction (1: negative)
  input  wire [TW-1:0] steplen_i,
  input  wire [TW-1:0] stepspace_i,
  input  wire [TW-1:0] dirsetup_i,
  input  wire [TW-1:0] dirhold_i,
  output wire          step_o,      // before the block's polarity
  output wire          dir_o,
  output wire          hold_o,      // the core must not iterate in this cycle
  output wire          rise_o,      // a pulse starts on this edge
  output wire          rise_dir_o,  // its direction
  output wire          busy_o       // a step waits or a pulse is out
);

  reg          step_q /* verilator public_flat_rd */;  // the step output
  reg          dir_q  /* verilator public_flat_rd */;  // the direction output
  reg          pend_q /* verilator public_flat_rd */;  // a core step waits
  reg          pdir_q /* verilator public_flat_rd */;  // its direction
  reg [TW-1:0] tf_q   /* verilator public_flat_rd */;  // cycles the step output has held its level (saturates)
  reg [TW-1:0] ts_q   /* verilator public_flat_rd */;  // cycles the direction output has held (saturates)

  localparam [TW-1:0] One = TW'(1);
  wire [TW-1:0] len   = steplen_i == '0 ? One : steplen_i;
  wire [TW-1:0] space = stepspace_i == '0 ? One : stepspace_i;

  wire fall   = step_q & (tf_q >= len);
  // The direction may change once the last pulse has held it dirhold cycles after its fall.
  wire dir_ok = step_q ? (fall & (dirhold_i == '0)) : (tf_q >= dirhold_i);
  wire change = pend_q & (pdir_q != dir_q) & dir_ok;
  wire dir_d  = change ? pdir_q : dir_q;
  wire [TW-1:0] ts_now = change ? '0 : ts_q;
  wire rise   = pend_q & ~step_q & (tf_q >= space) & (dir_d == pdir_q) & (ts_now >= dirsetup_i);
  wire [TW-1:0] tf_inc = &tf_q ? tf_q : tf_q + One;
  wire [TW-1:0] ts_inc = &ts_q ? ts_q : ts_q + One;

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      step_q <= 1'b0;
      dir_q  <= 1'b0;
      pend_q <= 1'b0;
      pdir_q <= 1'b0;
      tf_q   <= '1;
      ts_q   <= '1;
    end else begin
      step_q <= rise | (step_q & ~fall);
      dir_q  <= dir_d;
      tf_q   <= (rise | fall) ? One : tf_inc;
      ts_q   <= change ? One : ts_inc;
      pend_q <= ~flush_i & ((pend_q & ~rise) | step_i);
      if (step_i) pdir_q <= dir_i;
    end
  end

  assign step_o     = step_q;
  assign dir_o      = dir_q;
  assign hold_o     = (pend_q & ~rise) | step_i;
  assign rise_o     = rise;
  assign rise_dir_o = pdir_q;
  assign busy_o     = pend_q | step_q;

`ifndef SYNTHESIS
  // Assertions (rtl/dda_assert.vh): the block stops the core in time (a core step never
  // finds the buffer full), and the direction never changes while a pulse is high.
  always @(posedge clk_i) begin
    if (rst_ni) begin
      `DDA_ASSERT(flush_i || !(pend_q && !rise && step_i), "ASSERTION dda_stepdir: a core step while one waits")
      `DDA_ASSERT(!change || !step_q || fall, "ASSERTION dda_stepdir: the direction changes during a pulse")
    end
  end
`endif

endmodule
