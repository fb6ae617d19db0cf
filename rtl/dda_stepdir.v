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
// let it out. hold_o stops the core in a cycle only when a step its iteration could make
// (whether or not it makes one) could not enter the buffer: a step waits after this edge and will not leave on
// the next one (the next edge's rise, computed from this edge's next state), so no step
// is dropped, merged or reordered and the core is not held when the timings allow its
// pace. rise_o marks the edge on which a pulse starts (the block counts the position
// there, in the direction rise_dir_o). flush_i (abort) empties the buffer: the step
// waiting in it does not start, a pulse already out finishes its steplen. pend_o and
// pdir_o show the waiting step (the block stops a step toward an active limit). tag_i (the core's done_o) marks the step waiting
// after this edge, if any, as the finished piece's last: tag_left_o is high while it
// waits (the block counts the piece done once no tagged step waits).
`include "dda_assert.vh"

module dda_stepdir #(
  parameter integer TW = 12
) (
  input  wire          clk_i,
  input  wire          rst_ni,
  input  wire          flush_i,
  input  wire          step_i,      // the core's step pulse (registered in the core)
  input  wire          dir_i,       // its direction (1: negative)
  input  wire          tag_i,       // the core finished a piece in this cycle
  input  wire [TW-1:0] steplen_i,
  input  wire [TW-1:0] stepspace_i,
  input  wire [TW-1:0] dirsetup_i,
  input  wire [TW-1:0] dirhold_i,
  output wire          step_o,      // before the block's polarity
  output wire          dir_o,
  output wire          hold_o,      // the core must not iterate in this cycle
  output wire          rise_o,      // a pulse starts on this edge
  output wire          rise_dir_o,  // its direction
  output wire          wait_o,      // a step waits after this edge
  output wire          tag_left_o,  // a finished piece's last step still waits after this edge
  output wire          busy_o,      // a core step arrives, a step waits or a pulse is out
  output wire          pend_o,      // a step waits in this cycle
  output wire          pdir_o       // its direction
);

  reg          step_q /* verilator public_flat_rd */;  // the step output
  reg          dir_q  /* verilator public_flat_rd */;  // the direction output
  reg          pend_q /* verilator public_flat_rd */;  // a core step waits
  reg          pdir_q /* verilator public_flat_rd */;  // its direction
  reg [TW-1:0] tf_q   /* verilator public_flat_rd */;  // cycles the step output has held its level (saturates)
  reg [TW-1:0] ts_q   /* verilator public_flat_rd */;  // cycles the direction output has held (saturates)
  reg          tag_q  /* verilator public_flat_rd */;  // the waiting step is a finished piece's last

  localparam [TW-1:0] One = TW'(1);
  wire [TW-1:0] len   = steplen_i == '0 ? One : steplen_i;
  wire [TW-1:0] space = stepspace_i == '0 ? One : stepspace_i;

  wire [TW-1:0] tf_inc = &tf_q ? tf_q : tf_q + One;
  wire [TW-1:0] ts_inc = &ts_q ? ts_q : ts_q + One;
  // Every comparison is on the registers, side by side; the next state's ones are chosen
  // below by what this edge does (tf_d is 1 or tf_inc, ts_d is 1 or ts_inc), which keeps
  // the path into hold_o (and the core's ce_i) short.
  wire tf_ge_len      = tf_q >= len;
  wire tf_ge_space    = tf_q >= space;
  wire tf_ge_hold     = tf_q >= dirhold_i;
  wire ts_ge_setup    = ts_q >= dirsetup_i;
  // (a count one up reaches a bound it had reached, or one it now equals)
  wire inc_ge_space   = tf_ge_space | (tf_inc == space);
  wire inc_ge_hold    = tf_ge_hold | (tf_inc == dirhold_i);
  wire tsinc_ge_setup = ts_ge_setup | (ts_inc == dirsetup_i);
  wire hold0          = dirhold_i == '0;
  wire setup0         = dirsetup_i == '0;
  wire hold_le1       = dirhold_i <= One;
  wire setup_le1      = dirsetup_i <= One;
  wire space1         = space == One;

  wire fall   = step_q & tf_ge_len;
  // The direction may change once the last pulse has held it dirhold cycles after its fall.
  wire dir_ok = step_q ? (fall & hold0) : tf_ge_hold;
  wire change = pend_q & (pdir_q != dir_q) & dir_ok;
  wire dir_d  = change ? pdir_q : dir_q;
  wire rise   = pend_q & ~step_q & tf_ge_space & (dir_d == pdir_q) & (change ? setup0 : ts_ge_setup) & ~flush_i;

  // The next state, and whether a step waiting then leaves on the next edge.
  wire          step_d = rise | (step_q & ~fall);
  wire [TW-1:0] tf_d   = (rise | fall) ? One : tf_inc;
  wire [TW-1:0] ts_d   = change ? One : ts_inc;
  wire          pend_d = (pend_q & ~rise) | step_i;
  wire          pdir_d = step_i ? dir_i : pdir_q;
  wire          turn_n = pdir_d != dir_d;
  wire          tfd_ge_space = (rise | fall) ? space1 : inc_ge_space;
  wire          tfd_ge_hold  = (rise | fall) ? hold_le1 : inc_ge_hold;
  wire          tsd_ge_setup = change ? setup_le1 : tsinc_ge_setup;
  wire          rise_n = ~step_d & tfd_ge_space & (turn_n ? tfd_ge_hold & setup0 : tsd_ge_setup);

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      step_q <= 1'b0;
      dir_q  <= 1'b0;
      pend_q <= 1'b0;
      pdir_q <= 1'b0;
      tf_q   <= '1;
      ts_q   <= '1;
      tag_q  <= 1'b0;
    end else begin
      step_q <= step_d;
      dir_q  <= dir_d;
      tf_q   <= tf_d;
      ts_q   <= ts_d;
      pend_q <= ~flush_i & pend_d;
      pdir_q <= pdir_d;
      tag_q  <= ~flush_i & (tag_i ? pend_d : tag_q & ~rise);
    end
  end

  assign step_o     = step_q;
  assign dir_o      = dir_q;
  assign hold_o     = pend_d & ~rise_n;
  assign wait_o     = pend_d;
  assign tag_left_o = tag_q & ~rise;
  assign rise_o     = rise;
  assign rise_dir_o = pdir_q;
  assign busy_o     = step_i | pend_q | step_q;
  assign pend_o     = pend_q;
  assign pdir_o     = pdir_q;

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
