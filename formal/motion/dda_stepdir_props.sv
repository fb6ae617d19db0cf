// SPDX-License-Identifier: Apache-2.0
// The step/dir stage (rtl/dda_stepdir.v) at the block's timing width, under any core
// steps the block lets in, any flush and tag, and any four timings held constant
// (scripts/formal-bus.sh stepdir). Proven by k-induction, from the output pins and the
// stage's inputs only (the monitors below count levels of step_o and dir_o as a drive
// sees them):
//   steplen    every pulse is high for exactly max(steplen, 1) cycles;
//   stepspace  the step pin is low for at least max(stepspace, 1) cycles between pulses;
//   dirsetup   a pulse rises with the direction held at least dirsetup cycles (a change on
//              the rising edge itself only with dirsetup 0);
//   dirhold    the direction changes only with the step pin low, at least dirhold cycles
//              after the last fall (on the falling edge itself only with dirhold 0);
//   buffer     one step waits at most: every pulse starts for a step that waited, in its
//              direction; a step arriving is never dropped or merged (the block holds the
//              core while hold_o is high); a flush empties the buffer;
//   pace       the core is held only when it must be: in a cycle with hold_o high a step
//              waits after the edge and does not leave on the next one.
// The monitors' counts equal the stage's own counters (tf_q, ts_q, pend_q, pdir_q; renamed
// to outputs f_<name> by the script): asserted too, they make the properties inductive.
`include "dda_motion_regs.vh"

module dda_formal_stepdir (
  input wire          clk_i,
  input wire          rst_ni,
  input wire          flush_i,
  input wire          step_i,
  input wire          dir_i,
  input wire          tag_i,
  input wire [`DDA_MOTION_TIMING_WIDTH-1:0] steplen_i,
  input wire [`DDA_MOTION_TIMING_WIDTH-1:0] stepspace_i,
  input wire [`DDA_MOTION_TIMING_WIDTH-1:0] dirsetup_i,
  input wire [`DDA_MOTION_TIMING_WIDTH-1:0] dirhold_i
);
  localparam integer TW = `DDA_MOTION_TIMING_WIDTH;
  localparam [TW-1:0] One = TW'(1);
  wire step_o, dir_o, hold_o, rise_o, rise_dir_o, wait_o, tag_left_o, busy_o, pend_o, pdir_o;
  wire [TW-1:0] tf_q, ts_q;
  wire pend_q, pdir_q;

  dda_stepdir dut (  // its default TW, the block's timing width
    .clk_i(clk_i), .rst_ni(rst_ni), .flush_i(flush_i), .step_i(step_i), .dir_i(dir_i), .tag_i(tag_i),
    .steplen_i(steplen_i), .stepspace_i(stepspace_i), .dirsetup_i(dirsetup_i), .dirhold_i(dirhold_i),
    .step_o(step_o), .dir_o(dir_o), .hold_o(hold_o), .rise_o(rise_o), .rise_dir_o(rise_dir_o), .wait_o(wait_o),
    .tag_left_o(tag_left_o), .busy_o(busy_o), .pend_o(pend_o), .pdir_o(pdir_o),
    .f_tf_q(tf_q), .f_ts_q(ts_q), .f_pend_q(pend_q), .f_pdir_q(pdir_q)
  );

  // Reset first; then the timings stay as they are, and a core step comes only in a
  // cycle after one in which the stage did not hold the core (the block's ce_i).
  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @(*) if (!f_past) assume (!rst_ni);
  reg [TW-1:0] f_len0, f_space0, f_setup0, f_hold0;
  reg f_held = 1'b0;
  always @(posedge clk_i) begin
    f_len0   <= steplen_i;
    f_space0 <= stepspace_i;
    f_setup0 <= dirsetup_i;
    f_hold0  <= dirhold_i;
    f_held   <= rst_ni & hold_o;
  end
  always @(*) begin
    if (f_past) begin
      assume (steplen_i == f_len0 && stepspace_i == f_space0 && dirsetup_i == f_setup0 && dirhold_i == f_hold0);
      assume (!(f_held && step_i));
    end
  end

  wire [TW-1:0] len   = steplen_i == '0 ? One : steplen_i;
  wire [TW-1:0] space = stepspace_i == '0 ? One : stepspace_i;

  // The pins in the cycle before, and how many cycles each had held its level then
  // (1 in the first cycle of a level; saturating; after reset as if held forever).
  reg f_step_p = 1'b0, f_dir_p = 1'b0;
  reg [TW-1:0] f_lvl_p = '1, f_dlvl_p = '1;
  wire [TW-1:0] f_lvl  = step_o != f_step_p ? One : (&f_lvl_p ? f_lvl_p : f_lvl_p + One);
  wire [TW-1:0] f_dlvl = dir_o != f_dir_p ? One : (&f_dlvl_p ? f_dlvl_p : f_dlvl_p + One);
  wire rose = step_o && !f_step_p;
  wire fell = !step_o && f_step_p;
  wire turned = dir_o != f_dir_p;
  // The one-step buffer as the pins and the inputs tell it: a core step waits from the
  // edge that takes it until the edge a pulse rises for it.
  reg f_in_p = 1'b0, f_indir_p = 1'b0, f_flush_p = 1'b0;
  reg f_wait_p = 1'b0, f_wdir_p = 1'b0;
  wire f_wait = !f_flush_p && ((f_wait_p && !rose) || f_in_p);
  wire f_wdir = f_in_p ? f_indir_p : f_wdir_p;
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      f_step_p <= 1'b0;
      f_dir_p  <= 1'b0;
      f_lvl_p  <= '1;
      f_dlvl_p <= '1;
      f_in_p   <= 1'b0;
      f_flush_p <= 1'b0;
      f_wait_p <= 1'b0;
      f_wdir_p <= 1'b0;
    end else begin
      f_step_p <= step_o;
      f_dir_p  <= dir_o;
      f_lvl_p  <= f_lvl;
      f_dlvl_p <= f_dlvl;
      f_in_p   <= step_i;
      f_indir_p <= dir_i;
      f_flush_p <= flush_i;
      f_wait_p <= f_wait;
      f_wdir_p <= f_wdir;
    end
  end
  reg f_live = 1'b0;  // a cycle after reset has ended (the monitors have seen an edge)
  always @(posedge clk_i) f_live <= rst_ni;
  reg f_held2 = 1'b0, f_flush2 = 1'b0, f_live2 = 1'b0;  // two cycles before
  always @(posedge clk_i) begin
    f_held2  <= f_held;
    f_flush2 <= f_flush_p;
    f_live2  <= f_live;
  end

  always @(*) begin
    if (f_live && rst_ni) begin
      // The four timings.
      if (fell) assert (f_lvl_p == len);
      if (rose) assert (f_lvl_p >= space);
      if (rose && turned) assert (dirsetup_i == '0);
      if (rose && !turned) assert (f_dlvl_p >= dirsetup_i);
      if (turned && f_step_p) assert (!step_o && dirhold_i == '0);
      if (turned && !f_step_p) assert (f_lvl_p >= dirhold_i);
      // The buffer: a pulse only for a waiting step, in its direction; a step arriving
      // finds the buffer empty, or the waiting step leaving on that edge.
      if (rose) assert (f_wait_p && !f_flush_p && dir_o == f_wdir_p);
      if (f_in_p && !f_flush_p) assert (!f_wait_p || rose);
      // Held two cycles ago (and not flushed then): the step waiting after that cycle's
      // edge did not leave on the next.
      if (f_live2 && f_held2 && !f_flush2) assert (f_wait_p && !rose);
      // The monitors are the stage's counters (what makes these inductive).
      assert (f_lvl == tf_q && f_dlvl == ts_q);
      assert (f_wait == pend_q && (!pend_q || f_wdir == pdir_q));
    end
  end

endmodule
