// SPDX-License-Identifier: Apache-2.0
// The machine side of the motion block (docs/design.md, "Machine inputs"): the E-stop,
// limit, home and probe inputs, each through rtl/dda_input.v (INPUTS, IN_POLARITY,
// IN_FILTER), what they stop (IN_MODE, TRIP, LATCH_*), the probe's latch (PROBE_*) and
// the snapshot (SNAP_*) with the free-running cycle counter. The block (rtl/dda_motion.v,
// instance u_io) hands it the bus writes it decoded, the positions and the steps that
// enter or wait in the step/dir stages; it answers with the stops to make on this edge,
// the interrupt and error causes, its status bits and its registers' read data.
//   E-stop: while the filtered input is active, and after it until CTRL.clear, every
//     edge stops as CTRL.hard_stop does (STATUS.err_estop, TRIP.estop).
//   Limits: a step toward an active limit, entering a stage (the core's step routed to
//     it) or waiting in one, stops the motion: as CTRL.hard_stop (the step is dropped)
//     or, with IN_MODE.limit_decel, as CTRL.soft_stop (STATUS.err_limit, TRIP.limit_*).
//     Steps away from it go on.
//   Home: in homing mode (IN_MODE.home_*) the home input's active edge stops as
//     CTRL.soft_stop (TRIP.home_*, IRQ_STATUS.home).
//   LATCH_*: the positions on the first trip after TRIP was 0.
//   Probe: armed by CTRL.probe_arm, its next active edge latches PROBE_* (STATUS.probed,
//     IRQ_STATUS.probe) and, with IN_MODE.probe_stop, stops as CTRL.soft_stop.
//   Snapshot: CTRL.snapshot latches the positions, the cycle counter, the queue level
//     and DONE_COUNT of the same clock.
// Each latch takes the values the registers hold during the cycle of the event (before
// the edge): the positions count the pulses started up to that cycle.
`include "dda_motion_regs.vh"

module dda_motion_io #(
  parameter integer LW   = 8,  // queue level bits
  parameter integer Axes = 3   // the block's (2: the Z limits and home not built, held in reset)
) (
  input  wire                              clk_i,
  input  wire                              rst_ni,
  // the machine's pins (asynchronous)
  input  wire                              estop_ni,
  input  wire [5:0]                        limit_i,   // {z+, z-, y+, y-, x+, x-}
  input  wire [2:0]                        home_i,    // {z, y, x}
  input  wire                              probe_i,
  // the block's bus decode: a register write (wdat: merged with the register's value
  // in the lanes not selected), the CTRL bits written 1
  input  wire                              wr_i,
  input  wire [`DDA_MOTION_ADDR_WIDTH-1:0] adr_i,
  input  wire [31:0]                       wdat_i,
  input  wire                              clear_i,
  input  wire                              snapshot_i,
  input  wire                              probe_arm_i,
  // what the latches take
  input  wire [31:0]                       pos_x_i,
  input  wire [31:0]                       pos_y_i,
  input  wire [31:0]                       pos_z_i,
  input  wire [LW-1:0]                     level_i,
  input  wire [31:0]                       done_count_i,
  // per stage {z, y, x}: the step entering it on this edge and one waiting in it
  input  wire [2:0]                        step_i,
  input  wire [2:0]                        dir_i,     // 1: negative
  input  wire [2:0]                        pend_i,
  input  wire [2:0]                        pdir_i,
  output wire                              hard_o,    // stop on this edge, as an abort
  output wire                              soft_o,    // start a soft stop
  output wire                              err_o,     // an error cause on this edge (E-stop, limit)
  output wire                              probe_o,   // the probe latched on this edge
  output wire                              home_o,    // a home input stopped the motion
  output wire                              err_estop_o,
  output wire                              err_limit_o,
  output wire                              probe_armed_o,
  output wire                              probed_o,
  output reg  [31:0]                       rd_o       // read data at adr_i (0 for other registers)
);

  localparam integer SW = `DDA_MOTION_IN_FILTER_SWITCHES_WIDTH;  // a switch's filter, in ticks
  localparam integer TW = `DDA_MOTION_IN_FILTER_TICK_WIDTH;      // the switches' tick
  localparam integer FW = `DDA_MOTION_IN_FILTER_PROBE_WIDTH;     // the probe's filter, in clocks
  localparam integer NI = `DDA_MOTION_INPUTS;     // inputs (model/motion/motion_map.hpp kInputs)
  localparam integer NT = `DDA_MOTION_TRIP_BITS;  // TRIP's bits: every input but the probe

  reg [NI-1:0]  pol_q         /* verilator public_flat_rd */;
  reg [SW-1:0]  filt_sw_q     /* verilator public_flat_rd */;
  reg [TW-1:0]  filt_tick_q   /* verilator public_flat_rd */;
  reg [FW-1:0]  filt_probe_q  /* verilator public_flat_rd */;
  reg [4:0]     mode_q        /* verilator public_flat_rd */;  // IN_MODE
  reg           err_estop_q   /* verilator public_flat_rd */;
  reg           err_limit_q   /* verilator public_flat_rd */;
  reg [NT-1:0]  trip_q        /* verilator public_flat_rd */;
  reg [31:0]    latch_x_q     /* verilator public_flat_rd */;
  reg [31:0]    latch_y_q     /* verilator public_flat_rd */;
  reg [31:0]    latch_z_q     /* verilator public_flat_rd */;
  reg           probe_armed_q /* verilator public_flat_rd */;
  reg           probed_q      /* verilator public_flat_rd */;
  reg [31:0]    probe_x_q     /* verilator public_flat_rd */;
  reg [31:0]    probe_y_q     /* verilator public_flat_rd */;
  reg [31:0]    probe_z_q     /* verilator public_flat_rd */;
  reg [31:0]    snap_x_q      /* verilator public_flat_rd */;
  reg [31:0]    snap_y_q      /* verilator public_flat_rd */;
  reg [31:0]    snap_z_q      /* verilator public_flat_rd */;
  reg [31:0]    snap_cycle_q  /* verilator public_flat_rd */;
  reg [LW-1:0]  snap_level_q  /* verilator public_flat_rd */;
  reg [31:0]    snap_done_q   /* verilator public_flat_rd */;
  reg [31:0]    cycle_q       /* verilator public_flat_rd */;

  // ---- the inputs, in INPUTS' bit order; estop_ni is active low unless inverted ----
  wire [NI-1:0] pins   = {probe_i, home_i, limit_i, estop_ni};
  wire [NI-1:0] invert = pol_q ^ NI'(1);
  wire [NI-1:0] lvl, rise;
  // The switches' filters count on the clocks whose cycle count has its low filt_tick_q
  // bits all 1 (the cycle counter is their prescaler); the probe's on every clock.
  localparam integer PW = (1 << TW) - 1;
  wire [PW-1:0] tick_mask = PW'((32'd1 << filt_tick_q) - 32'd1);
  wire          sw_tick   = &(cycle_q[PW-1:0] | ~tick_mask);
  dda_input #(.FW(SW)) u_estop (.clk_i(clk_i), .rst_ni(rst_ni), .pin_i(pins[0]), .invert_i(invert[0]),
                                .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[0]), .rise_o(rise[0]));
  dda_input #(.FW(SW)) u_lxn (.clk_i(clk_i), .rst_ni(rst_ni), .pin_i(pins[1]), .invert_i(invert[1]),
                              .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[1]), .rise_o(rise[1]));
  dda_input #(.FW(SW)) u_lxp (.clk_i(clk_i), .rst_ni(rst_ni), .pin_i(pins[2]), .invert_i(invert[2]),
                              .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[2]), .rise_o(rise[2]));
  dda_input #(.FW(SW)) u_lyn (.clk_i(clk_i), .rst_ni(rst_ni), .pin_i(pins[3]), .invert_i(invert[3]),
                              .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[3]), .rise_o(rise[3]));
  dda_input #(.FW(SW)) u_lyp (.clk_i(clk_i), .rst_ni(rst_ni), .pin_i(pins[4]), .invert_i(invert[4]),
                              .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[4]), .rise_o(rise[4]));
  dda_input #(.FW(SW)) u_lzn (.clk_i(clk_i), .rst_ni(rst_ni & (Axes == 3)), .pin_i(pins[5]), .invert_i(invert[5]),
                              .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[5]), .rise_o(rise[5]));
  dda_input #(.FW(SW)) u_lzp (.clk_i(clk_i), .rst_ni(rst_ni & (Axes == 3)), .pin_i(pins[6]), .invert_i(invert[6]),
                              .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[6]), .rise_o(rise[6]));
  dda_input #(.FW(SW)) u_hx (.clk_i(clk_i), .rst_ni(rst_ni), .pin_i(pins[7]), .invert_i(invert[7]),
                             .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[7]), .rise_o(rise[7]));
  dda_input #(.FW(SW)) u_hy (.clk_i(clk_i), .rst_ni(rst_ni), .pin_i(pins[8]), .invert_i(invert[8]),
                             .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[8]), .rise_o(rise[8]));
  dda_input #(.FW(SW)) u_hz (.clk_i(clk_i), .rst_ni(rst_ni & (Axes == 3)), .pin_i(pins[9]), .invert_i(invert[9]),
                             .tick_i(sw_tick), .filter_i(filt_sw_q), .level_o(lvl[9]), .rise_o(rise[9]));
  dda_input #(.FW(FW)) u_probe (.clk_i(clk_i), .rst_ni(rst_ni), .pin_i(pins[10]), .invert_i(invert[10]),
                                .tick_i(1'b1), .filter_i(filt_probe_q), .level_o(lvl[10]), .rise_o(rise[10]));
  wire unused_rise = &{1'b0, rise[6:0]};
  // (IN_FILTER's bits between the switches' tick and the probe's filter are reserved.)
  wire unused_wdat = &{1'b0, wdat_i[`DDA_MOTION_IN_FILTER_PROBE_LSB-1:`DDA_MOTION_IN_FILTER_TICK_LSB+TW]};

  // ---- what stops the motion on this edge ----
  wire       estop = lvl[0];
  // Stage j's limits: negative lvl[1 + 2j], positive lvl[2 + 2j].
  wire [2:0] lim_neg = {lvl[5], lvl[3], lvl[1]};
  wire [2:0] lim_pos = {lvl[6], lvl[4], lvl[2]};
  wire [2:0] hit_neg = ((step_i & dir_i) | (pend_i & pdir_i)) & lim_neg;
  wire [2:0] hit_pos = ((step_i & ~dir_i) | (pend_i & ~pdir_i)) & lim_pos;
  wire [5:0] limit_hits = {hit_pos[2], hit_neg[2], hit_pos[1], hit_neg[1], hit_pos[0], hit_neg[0]};
  wire       limit_hit  = |limit_hits;
  wire [2:0] home_ev    = rise[9:7] & mode_q[`DDA_MOTION_IN_MODE_HOME_X_LSB+:3];
  wire       probe_ev   = rise[10] & probe_armed_q;
  wire       limit_decel = mode_q[`DDA_MOTION_IN_MODE_LIMIT_DECEL_LSB];
  wire [NT-1:0] trip_now = {home_ev, limit_hits, estop};

  assign hard_o        = estop | err_estop_q | (limit_hit & ~limit_decel);
  assign soft_o        = (limit_hit & limit_decel) | (|home_ev) |
                         (probe_ev & mode_q[`DDA_MOTION_IN_MODE_PROBE_STOP_LSB]);
  assign err_o         = estop | limit_hit;
  assign probe_o       = probe_ev;
  assign home_o        = |home_ev;
  assign err_estop_o   = err_estop_q;
  assign err_limit_o   = err_limit_q;
  assign probe_armed_o = probe_armed_q;
  assign probed_o      = probed_q;

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      pol_q         <= '0;
      filt_sw_q     <= '0;
      filt_tick_q   <= '0;
      filt_probe_q  <= '0;
      mode_q        <= '0;
      err_estop_q   <= 1'b0;
      err_limit_q   <= 1'b0;
      trip_q        <= '0;
      latch_x_q     <= '0;
      latch_y_q     <= '0;
      latch_z_q     <= '0;
      probe_armed_q <= 1'b0;
      probed_q      <= 1'b0;
      probe_x_q     <= '0;
      probe_y_q     <= '0;
      probe_z_q     <= '0;
      snap_x_q      <= '0;
      snap_y_q      <= '0;
      snap_z_q      <= '0;
      snap_cycle_q  <= '0;
      snap_level_q  <= '0;
      snap_done_q   <= '0;
      cycle_q       <= '0;
    end else begin
      if (wr_i && adr_i == `DDA_MOTION_IN_POLARITY_ADDR) pol_q <= wdat_i[NI-1:0];
      if (wr_i && adr_i == `DDA_MOTION_IN_FILTER_ADDR) begin
        filt_sw_q    <= wdat_i[`DDA_MOTION_IN_FILTER_SWITCHES_LSB+:SW];
        filt_tick_q  <= wdat_i[`DDA_MOTION_IN_FILTER_TICK_LSB+:TW];
        filt_probe_q <= wdat_i[`DDA_MOTION_IN_FILTER_PROBE_LSB+:FW];
      end
      if (wr_i && adr_i == `DDA_MOTION_IN_MODE_ADDR) mode_q <= wdat_i[4:0];
      // Sticky causes: a cause on the edge of a clear stays set.
      err_estop_q <= (err_estop_q & ~clear_i) | estop;
      err_limit_q <= (err_limit_q & ~clear_i) | limit_hit;
      trip_q      <= (trip_q & ~{NT{clear_i}}) | trip_now;
      if (trip_q == '0 && trip_now != '0) begin
        latch_x_q <= pos_x_i;
        latch_y_q <= pos_y_i;
        latch_z_q <= pos_z_i;
      end
      // An arm written on the edge of a probe event re-arms (and clears probed).
      probe_armed_q <= probe_arm_i | (probe_armed_q & ~probe_ev);
      probed_q      <= ~probe_arm_i & (probed_q | probe_ev);
      if (probe_ev) begin
        probe_x_q <= pos_x_i;
        probe_y_q <= pos_y_i;
        probe_z_q <= pos_z_i;
      end
      if (snapshot_i) begin
        snap_x_q     <= pos_x_i;
        snap_y_q     <= pos_y_i;
        snap_z_q     <= pos_z_i;
        snap_cycle_q <= cycle_q;
        snap_level_q <= level_i;
        snap_done_q  <= done_count_i;
      end
      cycle_q <= cycle_q + 32'd1;
    end
  end

  always @(*) begin
    rd_o = 32'd0;
    case (adr_i)
      `DDA_MOTION_INPUTS_ADDR:      rd_o[NI-1:0] = lvl;
      `DDA_MOTION_IN_POLARITY_ADDR: rd_o[NI-1:0] = pol_q;
      `DDA_MOTION_IN_FILTER_ADDR: begin
        rd_o[`DDA_MOTION_IN_FILTER_SWITCHES_LSB+:SW] = filt_sw_q;
        rd_o[`DDA_MOTION_IN_FILTER_TICK_LSB+:TW]     = filt_tick_q;
        rd_o[`DDA_MOTION_IN_FILTER_PROBE_LSB+:FW]    = filt_probe_q;
      end
      `DDA_MOTION_IN_MODE_ADDR:     rd_o[4:0] = mode_q;
      `DDA_MOTION_TRIP_ADDR:        rd_o[NT-1:0] = trip_q;
      `DDA_MOTION_LATCH_X_ADDR:     rd_o = latch_x_q;
      `DDA_MOTION_LATCH_Y_ADDR:     rd_o = latch_y_q;
      `DDA_MOTION_LATCH_Z_ADDR:     rd_o = latch_z_q;
      `DDA_MOTION_PROBE_X_ADDR:     rd_o = probe_x_q;
      `DDA_MOTION_PROBE_Y_ADDR:     rd_o = probe_y_q;
      `DDA_MOTION_PROBE_Z_ADDR:     rd_o = probe_z_q;
      `DDA_MOTION_SNAP_X_ADDR:      rd_o = snap_x_q;
      `DDA_MOTION_SNAP_Y_ADDR:      rd_o = snap_y_q;
      `DDA_MOTION_SNAP_Z_ADDR:      rd_o = snap_z_q;
      `DDA_MOTION_SNAP_CYCLE_ADDR:  rd_o = snap_cycle_q;
      `DDA_MOTION_SNAP_LEVEL_ADDR:  rd_o[LW-1:0] = snap_level_q;
      `DDA_MOTION_SNAP_DONE_ADDR:   rd_o = snap_done_q;
      default:                      rd_o = 32'd0;
    endcase
  end

endmodule
