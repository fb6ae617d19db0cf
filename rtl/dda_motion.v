// SPDX-License-Identifier: Apache-2.0
// The motion block (docs/design.md, "Motion block"): the DDA core behind a Wishbone B4
// slave, with a command queue in block RAM, status, interrupts, abort and a position
// counter per axis. The register map is rtl/dda_motion_regs.vh, generated from
// model/motion/motion_map.hpp (the one definition; docs/design.md and the firmware
// header fw/dda_motion_regs.h come from it too).
//
// Bus: 32-bit data, byte addresses (wb_adr_i[1:0] ignored). Byte lanes (wb_sel_i): a
// register write changes only the bytes of the lanes selected (the others keep their
// value; a CTRL bit acts and an IRQ_STATUS bit clears only in a selected lane); an entry
// word is written whole or not at all: a write to ENTRY with other lanes than all four
// is refused with a sticky error (err_lanes). A request (wb_cyc_i & wb_stb_i while wb_stall_o is low)
// is answered by wb_ack_o on the next cycle, read data with it; wb_stall_o is high in
// that cycle, so a classic master that holds wb_stb_i until the ack is not taken twice,
// and a pipelined master issues one request every other cycle. The bus never waits on
// the core.
//
// Queue: 2^DepthLog2 entries of ENTRY_WORDS words, each in ENTRY_ROWS rows of ROW_WORDS
// words (one EBR lane of 16 bits per half word of a row: a whole entry in one row would
// take more block RAMs than the HX8K has). After the head moves (or while the queue is
// empty) the RAM reads the head entry's row 0, which row0_q keeps on the next edge while
// the RAM reads row 1: the command is whole two edges after the head moved, so the core
// takes at most one entry every two clocks. The host writes the words of an entry
// (ENTRY + 4k) into the free slot at the tail and commits it (CTRL.commit).
// Refused, with a sticky error: an entry word or a commit while the queue is full
// (err_overflow), a commit before every word was written (err_partial), an entry word
// written with byte lanes (err_lanes). The core's
// err_o (a stalled command) sets err_stall.
// Abort (CTRL.abort): the core is reset on the edge that takes the write, the queue and
// the entry being written are flushed, the steps waiting in the step/dir stages are
// dropped (a pulse already out finishes its steplen), STATUS.aborted is set. A hard stop
// (CTRL.hard_stop) is an abort that also sets the sticky err_hard_stop. A soft stop
// (CTRL.soft_stop, or the watchdog running out: err_watchdog) holds the pace (paced
// pieces ramp to rest, others stop) and, once at rest with no step on its way to the
// pins, flushes as an abort does. The watchdog (WATCHDOG: a timeout in clocks, 0 off)
// restarts on every write to it.
// Machine inputs (docs/design.md, "Machine inputs"; rtl/dda_motion_io.v, u_io): the
// E-stop stops as a hard stop does, and keeps stopping every edge until CTRL.clear once
// released; a step toward an active limit stops as a hard or a soft stop (IN_MODE); a
// home input in homing mode and the armed probe (with IN_MODE.probe_stop) stop as a soft
// stop. CTRL.snapshot latches the positions, the queue level, DONE_COUNT and the cycle
// counter of one clock.
// Axes (docs/design.md, "Step and direction timing"): each core step goes through a
// step/dir stage (rtl/dda_stepdir.v) with the axis' four timings; the position counters
// count the pulses the stages start. Pace: an entry with a cruise speed (its pacing
// fields, docs/design.md "Pacer") is paced by the pacer (rtl/dda_pace.v, u_pace), which
// lets the core iterate at a path speed ramping at ACCEL between VMIN and the cruise
// speed times OVERRIDE, down to rest on a feed hold (CTRL.hold .. CTRL.resume). An entry
// without (cruise 0) is paced by its feed increment: a phase accumulator adds it every
// cycle the core may go on; its carry (or an increment of 0) lets the core iterate,
// unless a feed hold is on; while a stage holds the core the accumulator waits. A
// block built without the pacer (Pacer 0) paces every entry so, its cruise speed
// ignored: u_pace is held in reset and ACCEL, VMIN and OVERRIDE keep their reset values.
`include "dda_params.vh"
`include "dda_motion_regs.vh"

// The build-time choices (docs/design.md, "Builds"; their one definition:
// model/motion/build.hpp) are the parameters.
module dda_motion #(
  parameter integer DepthLog2 = `DDA_MOTION_MAX_DEPTH_LOG2,  // queue depth 2^DepthLog2 (1..7)
  parameter integer Inputs    = 1,  // 1: the machine inputs, latches and snapshot (u_io) are built in
  parameter integer Axes      = 3,  // 3: X, Y, Z; 2: X, Y (no linear axis, Z not built)
  parameter integer Pacer     = 1   // 1: the pacer (u_pace) is built in; 0: every entry runs at its feed increment
) (
  input  wire                              clk_i,
  input  wire                              rst_ni,      // synchronous, active low
  // Wishbone B4 slave
  input  wire                              wb_cyc_i,
  input  wire                              wb_stb_i,
  input  wire                              wb_we_i,
  input  wire [`DDA_MOTION_ADDR_WIDTH-1:0] wb_adr_i,
  input  wire [31:0]                       wb_dat_i,
  input  wire [3:0]                        wb_sel_i,
  output wire [31:0]                       wb_dat_o,
  output wire                              wb_ack_o,
  output wire                              wb_stall_o,
  // iteration enable of the core (high: one iteration per clock)
  input  wire                              ce_i,
  // the machine's inputs (asynchronous: each is synchronized and filtered)
  input  wire                              estop_ni,  // E-stop, active low (IN_POLARITY inverts)
  input  wire [5:0]                        limit_i,   // limits {z+, z-, y+, y-, x+, x-}
  input  wire [2:0]                        home_i,    // home switches {z, y, x}
  input  wire                              probe_i,   // touch probe
  // the axes
  output wire                              step_x_o,
  output wire                              step_y_o,
  output wire                              dir_x_o,
  output wire                              dir_y_o,
  output wire                              step_z_o,
  output wire                              dir_z_o,
  output wire                              busy_o,
  output wire                              irq_o
);

  // A build-time choice outside its range (kBuildParams, generated into
  // dda_motion_regs.vh) stops elaboration: the module instantiated for it does not
  // exist, so Yosys, Verilator and Icarus each fail and name it.
  generate
    if (DepthLog2 < `DDA_BUILD_DEPTHLOG2_MIN || DepthLog2 > `DDA_BUILD_DEPTHLOG2_MAX) begin : g_bad_depth_log2
      dda_motion_DepthLog2_out_of_range u_bad ();
    end
    if (Inputs < `DDA_BUILD_INPUTS_MIN || Inputs > `DDA_BUILD_INPUTS_MAX) begin : g_bad_inputs
      dda_motion_Inputs_out_of_range u_bad ();
    end
    if (Axes < `DDA_BUILD_AXES_MIN || Axes > `DDA_BUILD_AXES_MAX) begin : g_bad_axes
      dda_motion_Axes_out_of_range u_bad ();
    end
    if (Pacer < `DDA_BUILD_PACER_MIN || Pacer > `DDA_BUILD_PACER_MAX) begin : g_bad_pacer
      dda_motion_Pacer_out_of_range u_bad ();
    end
  endgenerate

  localparam integer Words = `DDA_MOTION_ENTRY_WORDS;
  localparam integer RowWords = `DDA_MOTION_ROW_WORDS;
  localparam integer Lanes    = 2 * RowWords;  // EBR lanes of a row
  localparam integer LW    = `DDA_MOTION_LEVEL_WIDTH;
  localparam [LW-1:0] Depth = LW'(1) << DepthLog2;
  localparam integer TW = `DDA_MOTION_TIMING_WIDTH;
  localparam integer FW = `DDA_MOTION_FEED_WIDTH;

  // ---- bus ----
  reg         ack_q /* verilator public_flat_rd */;
  reg  [31:0] dat_q /* verilator public_flat_rd */;
  wire        req   = wb_cyc_i & wb_stb_i & ~ack_q;
  wire        wr    = req & wb_we_i;
  wire [`DDA_MOTION_ADDR_WIDTH-1:0] adr = {wb_adr_i[`DDA_MOTION_ADDR_WIDTH-1:2], 2'b00};
  assign wb_ack_o   = ack_q;
  assign wb_stall_o = ack_q;
  assign wb_dat_o   = dat_q;
  wire unused_bus = &{1'b0, wb_adr_i[1:0]};
  // The write data in the lanes selected (wsel), and merged with the register's value
  // in the others (wdat; rd is the addressed register's read value).
  reg  [31:0] rd;
  wire [31:0] lanes = {{8{wb_sel_i[3]}}, {8{wb_sel_i[2]}}, {8{wb_sel_i[1]}}, {8{wb_sel_i[0]}}};
  wire [31:0] wsel  = wb_dat_i & lanes;
  wire [31:0] wdat  = (rd & ~lanes) | wsel;

  wire wr_ctrl   = wr & (adr == `DDA_MOTION_CTRL_ADDR);
  wire commit    = wr_ctrl & wsel[`DDA_MOTION_CTRL_COMMIT_LSB];
  wire hard_stop = wr_ctrl & wsel[`DDA_MOTION_CTRL_HARD_STOP_LSB];
  wire soft_stop = wr_ctrl & wsel[`DDA_MOTION_CTRL_SOFT_STOP_LSB];
  wire soft_flush;  // a soft stop at rest with no step on its way: its flush
  // The machine's inputs (u_io): stop on this edge (E-stop, a limit), start a soft stop
  // (a limit, a home input, the probe), an error cause, the probe latched, a home stop.
  wire io_hard, io_soft, io_err, io_probe, io_home;
  wire abort     = (wr_ctrl & wsel[`DDA_MOTION_CTRL_ABORT_LSB]) | hard_stop | soft_flush | io_hard;
  wire clear     = wr_ctrl & wsel[`DDA_MOTION_CTRL_CLEAR_LSB];
  wire hold_set  = wr_ctrl & wsel[`DDA_MOTION_CTRL_HOLD_LSB];
  wire hold_clr  = wr_ctrl & wsel[`DDA_MOTION_CTRL_RESUME_LSB];
  localparam [`DDA_MOTION_ADDR_WIDTH:0] EntryEnd = (`DDA_MOTION_ADDR_WIDTH+1)'(`DDA_MOTION_ENTRY_ADDR) + (`DDA_MOTION_ADDR_WIDTH+1)'(4 * Words);
  wire in_entry  = adr >= `DDA_MOTION_ENTRY_ADDR && {1'b0, adr} < EntryEnd;
  wire [`DDA_MOTION_ADDR_WIDTH-1:0] entry_off = adr - `DDA_MOTION_ENTRY_ADDR;
  wire [4:0] word = entry_off[6:2];  // the window holds at most 32 words
  wire unused_off = &{1'b0, entry_off[`DDA_MOTION_ADDR_WIDTH-1:7], entry_off[1:0]};

  // ---- queue ----
  reg  [DepthLog2-1:0] head_q  /* verilator public_flat_rd */;
  reg  [DepthLog2-1:0] tail_q  /* verilator public_flat_rd */;
  reg  [LW-1:0]        level_q /* verilator public_flat_rd */;
  reg  [Words-1:0]     mask_q  /* verilator public_flat_rd */;  // words written since the last commit
  reg  [1:0]           fetch_q /* verilator public_flat_rd */;  // rows of the head entry read: 0, 1 (row 0 at the RAM output), 2 (row 0 in row0_q, row 1 at the output)
  wire                 full  = level_q == Depth;
  wire                 empty = level_q == {LW{1'b0}};
  wire                 wr_entry  = wr & in_entry & ~abort;
  wire                 entry_ok  = wr_entry & ~full & (&wb_sel_i);
  wire                 err_lanes = wr_entry & ~(&wb_sel_i);
  wire                 commit_ok = commit & ~abort & ~full & (&mask_q);
  wire                 err_overflow = (wr_entry | commit) & ~abort & full;
  wire                 err_partial  = commit & ~abort & ~full & ~(&mask_q);

  wire        core_ready, core_busy, core_done, core_err, core_iter;
  wire        core_step_x, core_step_y, core_dir_x, core_dir_y;
  wire        core_step_z, core_dir_z;
  wire        cmd_valid = (fetch_q == 2'd2) & ~empty;
  wire        take      = cmd_valid & core_ready & ~abort;  // the core loads the head entry
  wire [DepthLog2-1:0] head_d = !rst_ni ? '0 : abort ? tail_q : take ? head_q + 1'b1 : head_q;
  wire [LW-1:0]        level_d = level_q + {{(LW-1){1'b0}}, commit_ok} - {{(LW-1){1'b0}}, take};
  // The row the RAM reads on this edge: row 0 of the head after it moves, while the
  // queue is empty (the host may be writing that slot) and after reset; else row 1.
  wire        refetch   = !rst_ni | empty | take | abort | (fetch_q == 2'd0);
  wire [1:0]  fetch_d   = refetch ? 2'd1 : 2'd2;

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      head_q   <= '0;
      tail_q   <= '0;
      level_q  <= '0;
      mask_q   <= '0;
      fetch_q  <= 2'd0;
    end else begin
      fetch_q  <= fetch_d;
      head_q   <= head_d;
      if (abort) begin
        level_q <= '0;
        mask_q  <= '0;
      end else begin
        level_q <= level_d;
        if (commit_ok) begin
          tail_q <= tail_q + 1'b1;
          mask_q <= '0;
        end else if (entry_ok) begin
          mask_q <= mask_q | (Words'(1) << word);
        end
      end
    end
  end

  // Entry word k is word k % RowWords of row k / RowWords.
  wire [16*Lanes-1:0] rd_row;
  reg  [16*Lanes-1:0] row0_q;
  wire                wr_row = word >= 5'(RowWords);
  wire [4:0]          wr_word = wr_row ? word - 5'(RowWords) : word;
  genvar l;
  for (l = 0; l < Lanes; l = l + 1) begin : g_lane
    (* no_rw_check *) reg [15:0] mem [0:(2 << DepthLog2)-1];
    reg [15:0] rd_q;
    always @(posedge clk_i) begin
      if (entry_ok && wr_word == 5'(l / 2)) mem[{tail_q, wr_row}] <= wb_dat_i[16*(l%2)+:16];
      rd_q <= mem[{head_d, fetch_d == 2'd2}];
    end
    assign rd_row[16*l+:16] = rd_q;
  end
  always @(posedge clk_i) if (fetch_q == 2'd1) row0_q <= rd_row;
  wire [32*`DDA_MOTION_ENTRY_ROWS*RowWords-1:0] entry_q = {rd_row, row0_q};
  // The feed increment: the top FW bits of the entry's last word; the axes: the bits
  // right above the command.
  localparam integer AxesBit = 32 * `DDA_MOTION_AXES_WORD + `DDA_MOTION_AXES_LSB;
  wire [FW-1:0] entry_feed = entry_q[32 * `DDA_MOTION_FEED_WORD + `DDA_MOTION_FEED_LSB +: FW];
  wire [1:0]    entry_axes = Axes == 3 ? entry_q[AxesBit +: 2] : 2'd0;  // (2 axes: the plane on X, Y)
  wire unused_entry = &{1'b0, entry_q[32 * `DDA_MOTION_FEED_WORD + `DDA_MOTION_FEED_LSB - 1:AxesBit + 2],
                       entry_q[32 * `DDA_MOTION_ENTRY_ROWS * RowWords - 1:32 * Words]};
  wire [31:0] entry_cruise = entry_q[32 * `DDA_MOTION_PACE_CRUISE_WORD +: 32];
  wire [31:0] entry_limit  = entry_q[32 * `DDA_MOTION_PACE_LIMIT_WORD +: 32];
  wire [31:0] entry_exit   = entry_q[32 * `DDA_MOTION_PACE_EXIT_WORD +: 32];
  wire [31:0] entry_length = entry_q[32 * `DDA_MOTION_PACE_LENGTH_WORD +: 32];
  wire [31:0] entry_brake  = entry_q[32 * `DDA_MOTION_PACE_BRAKE_EXIT_WORD +: 32];

  // ---- pace: the pacer, or the phase accumulator of the feed increment ----
  reg  [FW-1:0] feed_q /* verilator public_flat_rd */;  // the running entry's increment
  reg  [FW-1:0] acc_q  /* verilator public_flat_rd */;
  reg           paced_q     /* verilator public_flat_rd */;  // the running entry has a cruise speed
  reg           feed_hold_q /* verilator public_flat_rd */;
  reg  [31:0]   accel_q     /* verilator public_flat_rd */;
  reg  [31:0]   vmin_q      /* verilator public_flat_rd */;
  reg  [`DDA_MOTION_OVERRIDE_OVERRIDE_WIDTH-1:0] override_q /* verilator public_flat_rd */;
  wire          hold;                                   // a step/dir stage holds the core
  wire          advance = ce_i & ~hold;
  wire [FW:0]   acc_sum = {1'b0, acc_q} + {1'b0, feed_q};
  wire          pace_iterate;
  wire          core_busy_paced = core_busy & paced_q;
  reg           stopping_q  /* verilator public_flat_rd */;  // a soft stop runs
  wire          halt    = feed_hold_q | stopping_q;          // the pace heads for rest
  wire          core_ce = core_busy_paced ? pace_iterate
                        : advance & ~halt & (feed_q == '0 | acc_sum[FW]);

  // ---- the core ----
  // With 2 axes the core's linear axis is not built: its fields (the command's last, from
  // jv_z up: jv_z, jr_z, cap_z, cnt_z, dir_z) read as an idle axis's, every one 0 but
  // cap_z, 1 (motion::idle_linear_axis), so that synthesis keeps none of its logic.
  localparam integer ZLsb = `DDA_CMD_JV_Z_LSB;
  localparam integer CapZTop = `DDA_CMD_CAP_Z_LSB + `DDA_CMD_CAP_Z_WIDTH;
  wire [`DDA_CMD_WIDTH-1:0] core_cmd = Axes == 3 ? entry_q[`DDA_CMD_WIDTH-1:0]
      : {{(`DDA_CMD_WIDTH - CapZTop){1'b0}}, `DDA_CMD_CAP_Z_WIDTH'(1), {(`DDA_CMD_CAP_Z_LSB - ZLsb){1'b0}},
         entry_q[ZLsb-1:0]};
  wire unused_cmd = &{1'b0, entry_q[`DDA_CMD_WIDTH-1:ZLsb]};
  dda_core u_core (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni & ~abort),
    .ce_i        (core_ce),
    .cmd_valid_i (cmd_valid),
    .cmd_ready_o (core_ready),
    .cmd_i       (core_cmd),
    .step_x_o    (core_step_x),
    .step_y_o    (core_step_y),
    .dir_x_o     (core_dir_x),
    .dir_y_o     (core_dir_y),
    .step_z_o    (core_step_z),
    .dir_z_o     (core_dir_z),
    .busy_o      (core_busy),
    .done_o      (core_done),
    .err_o       (core_err),
    .iter_o      (core_iter),
    .norm_v_x_o  (norm_v_x),
    .norm_v_y_o  (norm_v_y),
    .norm_v_z_o  (norm_v_z),
    .norm_cap_o  (norm_cap),
    .norm_cap_z_o(norm_cap_z)
  );
  wire unused_core = &{1'b0, core_iter};

  // ---- the pacer ----
  wire [`DDA_ACC_WIDTH-1:0] norm_v_x, norm_v_y, norm_v_z, norm_cap, norm_cap_z;
  localparam integer PaceRF = 48;  // the pacer's speed fraction bits (kRampFrac), set on it below
  wire [PaceRF-1:0] pace_speed;
  dda_pace #(.RF(PaceRF)) u_pace (
    .clk_i        (clk_i),
    .rst_ni       (rst_ni & ~abort & (Pacer != 0)),  // not built (Pacer 0): held in reset
    .advance_i    (advance),
    .running_i    (core_busy_paced),
    .take_i       (take),
    .cruise_i     (entry_cruise),
    .limit_i      (entry_limit),
    .exit_i       (entry_exit),
    .length_i     (entry_length),
    .brake_exit_i (entry_brake),
    .next_queued_i(level_q > {{(LW-1){1'b0}}, take}),
    .accel_i      (accel_q),
    .vmin_i       (vmin_q),
    .override_i   (override_q),
    .hold_i       (halt),
    .stepped_i    (core_step_x | core_step_y | core_step_z),
    .v_x_i        (norm_v_x),
    .v_y_i        (norm_v_y),
    .v_z_i        (norm_v_z),
    .cap_i        (norm_cap),
    .cap_z_i      (norm_cap_z),
    .iterate_o    (pace_iterate),
    .speed_o      (pace_speed)
  );
  wire at_rest = pace_speed == '0;

  // ---- axes: which stage each of the core's axes drives ----
  // axes_q is the running entry's; route_q the one of the core's step outputs, which
  // show the iteration of the edge before (the finishing edge of a piece also loads the
  // next entry): axes_q a clock later.
  reg [1:0] axes_q  /* verilator public_flat_rd */;
  reg [1:0] route_q /* verilator public_flat_rd */;

  always @(posedge clk_i) begin
    if (!rst_ni || abort) begin
      feed_q  <= '0;
      acc_q   <= '0;
      paced_q <= 1'b0;
      axes_q  <= '0;
      route_q <= '0;
    end else begin
      if (take) feed_q <= entry_feed;
      if (advance & ~halt) acc_q <= acc_sum[FW-1:0];
      if (take) paced_q <= Pacer != 0 && entry_cruise != 32'd0;  // (no pacer: the feed increment paces)
      if (take) axes_q <= entry_axes;
      route_q <= axes_q;
    end
  end
  // The pacing settings; a feed hold outlasts an abort (a held machine stays held). The
  // watchdog: wd_cnt_q counts down from each write to WATCHDOG; it bites on its last
  // clock.
  localparam [31:0] OverrideMax = `DDA_MOTION_OVERRIDE_MAX;
  reg  [31:0] wd_q     /* verilator public_flat_rd */;
  reg  [31:0] wd_cnt_q /* verilator public_flat_rd */;
  wire        wr_wd = wr & (adr == `DDA_MOTION_WATCHDOG_ADDR);
  wire        bite  = ~wr_wd & (wd_cnt_q == 32'd1);
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      stopping_q <= 1'b0;
      wd_q       <= '0;
      wd_cnt_q   <= '0;
    end else begin
      stopping_q <= ~abort & (stopping_q | soft_stop | bite | io_soft);
      if (wr_wd) begin
        wd_q     <= wdat;
        wd_cnt_q <= wdat;
      end else if (wd_cnt_q != 32'd0) begin
        wd_cnt_q <= wd_cnt_q - 32'd1;
      end
    end
  end
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      feed_hold_q <= 1'b0;
      accel_q     <= '0;
      vmin_q      <= '0;
      override_q  <= `DDA_MOTION_OVERRIDE_OVERRIDE_WIDTH'(`DDA_MOTION_OVERRIDE_ONE);
    end else begin
      feed_hold_q <= hold_set | (feed_hold_q & ~hold_clr);
      if (wr && adr == `DDA_MOTION_ACCEL_ADDR && Pacer != 0) accel_q <= wdat;
      if (wr && adr == `DDA_MOTION_VMIN_ADDR && Pacer != 0) vmin_q <= wdat;
      if (wr && adr == `DDA_MOTION_OVERRIDE_ADDR && Pacer != 0)
        override_q <= wdat > OverrideMax ? OverrideMax[`DDA_MOTION_OVERRIDE_OVERRIDE_WIDTH-1:0]
                                         : wdat[`DDA_MOTION_OVERRIDE_OVERRIDE_WIDTH-1:0];
    end
  end
  // Stage j takes the core's axis (j - route) mod 3 (route 3 as 0).
  wire [2:0] c_step = {core_step_z, core_step_y, core_step_x};
  wire [2:0] c_dir  = {core_dir_z, core_dir_y, core_dir_x};
  wire [2:0] r_step = route_q == 2'd1 ? {c_step[1], c_step[0], c_step[2]}
                    : route_q == 2'd2 ? {c_step[0], c_step[2], c_step[1]} : c_step;
  wire [2:0] r_dir  = route_q == 2'd1 ? {c_dir[1], c_dir[0], c_dir[2]}
                    : route_q == 2'd2 ? {c_dir[0], c_dir[2], c_dir[1]} : c_dir;

  // ---- step/dir stages ----
  reg [TW-1:0] steplen_x_q   /* verilator public_flat_rd */;
  reg [TW-1:0] stepspace_x_q /* verilator public_flat_rd */;
  reg [TW-1:0] dirsetup_x_q  /* verilator public_flat_rd */;
  reg [TW-1:0] dirhold_x_q   /* verilator public_flat_rd */;
  reg [TW-1:0] steplen_y_q   /* verilator public_flat_rd */;
  reg [TW-1:0] stepspace_y_q /* verilator public_flat_rd */;
  reg [TW-1:0] dirsetup_y_q  /* verilator public_flat_rd */;
  reg [TW-1:0] dirhold_y_q   /* verilator public_flat_rd */;
  reg [TW-1:0] steplen_z_q   /* verilator public_flat_rd */;
  reg [TW-1:0] stepspace_z_q /* verilator public_flat_rd */;
  reg [TW-1:0] dirsetup_z_q  /* verilator public_flat_rd */;
  reg [TW-1:0] dirhold_z_q   /* verilator public_flat_rd */;
  reg [5:0]    polarity_q    /* verilator public_flat_rd */;  // {dir_z, step_z, dir_y, step_y, dir_x, step_x}
  wire sx_step, sx_dir, sx_hold, sx_rise, sx_rise_dir, sx_wait, sx_tag_left, sx_busy, sx_pend, sx_pdir;
  wire sy_step, sy_dir, sy_hold, sy_rise, sy_rise_dir, sy_wait, sy_tag_left, sy_busy, sy_pend, sy_pdir;
  wire sz_step, sz_dir, sz_hold, sz_rise, sz_rise_dir, sz_wait, sz_tag_left, sz_busy, sz_pend, sz_pdir;
  dda_stepdir #(.TW(TW)) u_sx (
    .clk_i(clk_i), .rst_ni(rst_ni), .flush_i(abort), .step_i(r_step[0]), .dir_i(r_dir[0]), .tag_i(core_done),
    .steplen_i(steplen_x_q), .stepspace_i(stepspace_x_q), .dirsetup_i(dirsetup_x_q), .dirhold_i(dirhold_x_q),
    .step_o(sx_step), .dir_o(sx_dir), .hold_o(sx_hold), .rise_o(sx_rise), .rise_dir_o(sx_rise_dir), .wait_o(sx_wait),
    .tag_left_o(sx_tag_left), .busy_o(sx_busy), .pend_o(sx_pend), .pdir_o(sx_pdir)
  );
  dda_stepdir #(.TW(TW)) u_sy (
    .clk_i(clk_i), .rst_ni(rst_ni), .flush_i(abort), .step_i(r_step[1]), .dir_i(r_dir[1]), .tag_i(core_done),
    .steplen_i(steplen_y_q), .stepspace_i(stepspace_y_q), .dirsetup_i(dirsetup_y_q), .dirhold_i(dirhold_y_q),
    .step_o(sy_step), .dir_o(sy_dir), .hold_o(sy_hold), .rise_o(sy_rise), .rise_dir_o(sy_rise_dir), .wait_o(sy_wait),
    .tag_left_o(sy_tag_left), .busy_o(sy_busy), .pend_o(sy_pend), .pdir_o(sy_pdir)
  );
  // (2 axes: Z not built, its stage held in reset)
  dda_stepdir #(.TW(TW)) u_sz (
    .clk_i(clk_i), .rst_ni(rst_ni & (Axes == 3)), .flush_i(abort), .step_i(r_step[2] & (Axes == 3)),
    .dir_i(r_dir[2] & (Axes == 3)), .tag_i(core_done & (Axes == 3)),
    .steplen_i(steplen_z_q), .stepspace_i(stepspace_z_q), .dirsetup_i(dirsetup_z_q), .dirhold_i(dirhold_z_q),
    .step_o(sz_step), .dir_o(sz_dir), .hold_o(sz_hold), .rise_o(sz_rise), .rise_dir_o(sz_rise_dir), .wait_o(sz_wait),
    .tag_left_o(sz_tag_left), .busy_o(sz_busy), .pend_o(sz_pend), .pdir_o(sz_pdir)
  );
  wire wr_step_x = wr & (adr == `DDA_MOTION_STEP_X_ADDR);
  wire wr_dir_x  = wr & (adr == `DDA_MOTION_DIR_X_ADDR);
  wire wr_step_y = wr & (adr == `DDA_MOTION_STEP_Y_ADDR);
  wire wr_dir_y  = wr & (adr == `DDA_MOTION_DIR_Y_ADDR);
  wire wr_step_z = wr & (adr == `DDA_MOTION_STEP_Z_ADDR);
  wire wr_dir_z  = wr & (adr == `DDA_MOTION_DIR_Z_ADDR);
  // A timing written on this edge is not in the stages' look-ahead: hold the core once.
  assign hold     = sx_hold | sy_hold | sz_hold | wr_step_x | wr_dir_x | wr_step_y | wr_dir_y | wr_step_z | wr_dir_z;
  assign step_x_o = sx_step ^ polarity_q[`DDA_MOTION_POLARITY_STEP_X_LSB];
  assign dir_x_o  = sx_dir ^ polarity_q[`DDA_MOTION_POLARITY_DIR_X_LSB];
  assign step_y_o = sy_step ^ polarity_q[`DDA_MOTION_POLARITY_STEP_Y_LSB];
  assign dir_y_o  = sy_dir ^ polarity_q[`DDA_MOTION_POLARITY_DIR_Y_LSB];
  assign step_z_o = sz_step ^ polarity_q[`DDA_MOTION_POLARITY_STEP_Z_LSB];
  assign dir_z_o  = sz_dir ^ polarity_q[`DDA_MOTION_POLARITY_DIR_Z_LSB];
  wire   busy     = core_busy | sx_busy | sy_busy | sz_busy;
  assign soft_flush = stopping_q & at_rest & ~(sx_busy | sy_busy | sz_busy);
  assign busy_o   = busy;
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      steplen_x_q   <= '0;
      stepspace_x_q <= '0;
      dirsetup_x_q  <= '0;
      dirhold_x_q   <= '0;
      steplen_y_q   <= '0;
      stepspace_y_q <= '0;
      dirsetup_y_q  <= '0;
      dirhold_y_q   <= '0;
      steplen_z_q   <= '0;
      stepspace_z_q <= '0;
      dirsetup_z_q  <= '0;
      dirhold_z_q   <= '0;
      polarity_q    <= '0;
    end else begin
      if (wr_step_x) begin
        steplen_x_q   <= wdat[`DDA_MOTION_STEP_X_STEPLEN_LSB+:TW];
        stepspace_x_q <= wdat[`DDA_MOTION_STEP_X_STEPSPACE_LSB+:TW];
      end
      if (wr_dir_x) begin
        dirsetup_x_q <= wdat[`DDA_MOTION_DIR_X_DIRSETUP_LSB+:TW];
        dirhold_x_q  <= wdat[`DDA_MOTION_DIR_X_DIRHOLD_LSB+:TW];
      end
      if (wr_step_y) begin
        steplen_y_q   <= wdat[`DDA_MOTION_STEP_Y_STEPLEN_LSB+:TW];
        stepspace_y_q <= wdat[`DDA_MOTION_STEP_Y_STEPSPACE_LSB+:TW];
      end
      if (wr_dir_y) begin
        dirsetup_y_q <= wdat[`DDA_MOTION_DIR_Y_DIRSETUP_LSB+:TW];
        dirhold_y_q  <= wdat[`DDA_MOTION_DIR_Y_DIRHOLD_LSB+:TW];
      end
      if (wr_step_z && Axes == 3) begin
        steplen_z_q   <= wdat[`DDA_MOTION_STEP_Z_STEPLEN_LSB+:TW];
        stepspace_z_q <= wdat[`DDA_MOTION_STEP_Z_STEPSPACE_LSB+:TW];
      end
      if (wr_dir_z && Axes == 3) begin
        dirsetup_z_q <= wdat[`DDA_MOTION_DIR_Z_DIRSETUP_LSB+:TW];
        dirhold_z_q  <= wdat[`DDA_MOTION_DIR_Z_DIRHOLD_LSB+:TW];
      end
      if (wr && adr == `DDA_MOTION_POLARITY_ADDR) polarity_q <= wdat[5:0] & (Axes == 3 ? 6'h3F : 6'h0F);
    end
  end

  // ---- status, interrupts, counters, positions ----
  reg        err_q          /* verilator public_flat_rd */;
  reg        err_overflow_q /* verilator public_flat_rd */;
  reg        err_partial_q  /* verilator public_flat_rd */;
  reg        err_lanes_q    /* verilator public_flat_rd */;
  reg        err_stall_q    /* verilator public_flat_rd */;
  reg        aborted_q      /* verilator public_flat_rd */;
  reg        err_hard_q     /* verilator public_flat_rd */;
  reg        err_watchdog_q /* verilator public_flat_rd */;
  reg [4:0]  irq_status_q   /* verilator public_flat_rd */;  // {home, probe, low, err, done}
  reg [4:0]  irq_enable_q   /* verilator public_flat_rd */;
  reg [LW-1:0] irq_level_q  /* verilator public_flat_rd */;
  reg [31:0] done_count_q   /* verilator public_flat_rd */;
  reg [31:0] err_count_q    /* verilator public_flat_rd */;
  reg [31:0] pos_x_q        /* verilator public_flat_rd */;
  reg [31:0] pos_y_q        /* verilator public_flat_rd */;
  reg [31:0] pos_z_q        /* verilator public_flat_rd */;

  wire err_set = err_overflow | err_partial | err_lanes | core_err | hard_stop | bite | io_err;
  wire low_set = take & (level_d < irq_level_q);
  // A piece is done when the core has finished it and its last steps have left the
  // stages: DONE_COUNT, IRQ_STATUS.done and the position counters agree. On the core's
  // done_o the stages tag the step waiting after the edge, if any (none of the next
  // piece's can wait yet); done_wait_q holds the piece until no tagged step waits. A
  // piece finished on the edge a tagged one leaves makes two on that edge.
  reg  done_wait_q /* verilator public_flat_rd */;
  wire tags_left = sx_tag_left | sy_tag_left | sz_tag_left;
  wire old_done  = done_wait_q & ~tags_left;
  wire new_wait  = core_done & (sx_wait | sy_wait | sz_wait);
  wire new_done  = core_done & ~new_wait;
  wire [4:0] irq_set = {io_home, io_probe, low_set, err_set, old_done | new_done};
  // The pulses the stages start on this edge: +1, -1 or 0.
  wire [31:0] dx = sx_rise ? (sx_rise_dir ? 32'hFFFF_FFFF : 32'd1) : 32'd0;
  wire [31:0] dy = sy_rise ? (sy_rise_dir ? 32'hFFFF_FFFF : 32'd1) : 32'd0;
  wire [31:0] dz = sz_rise ? (sz_rise_dir ? 32'hFFFF_FFFF : 32'd1) : 32'd0;
  wire wr_pos_x = wr & (adr == `DDA_MOTION_POS_X_ADDR);
  wire wr_pos_y = wr & (adr == `DDA_MOTION_POS_Y_ADDR);
  wire wr_pos_z = wr & (adr == `DDA_MOTION_POS_Z_ADDR);

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      err_q          <= 1'b0;
      err_overflow_q <= 1'b0;
      err_partial_q  <= 1'b0;
      err_lanes_q    <= 1'b0;
      err_stall_q    <= 1'b0;
      aborted_q      <= 1'b0;
      err_hard_q     <= 1'b0;
      err_watchdog_q <= 1'b0;
      irq_status_q   <= '0;
      irq_enable_q   <= '0;
      irq_level_q    <= '0;
      done_count_q   <= '0;
      done_wait_q    <= 1'b0;
      err_count_q    <= '0;
      pos_x_q        <= '0;
      pos_y_q        <= '0;
      pos_z_q        <= '0;
    end else begin
      // Sticky bits: a cause on the edge of a clear stays set.
      err_q          <= (err_q & ~clear) | err_set;
      err_overflow_q <= (err_overflow_q & ~clear) | err_overflow;
      err_partial_q  <= (err_partial_q & ~clear) | err_partial;
      err_lanes_q    <= (err_lanes_q & ~clear) | err_lanes;
      err_stall_q    <= (err_stall_q & ~clear) | core_err;
      aborted_q      <= (aborted_q & ~clear) | abort;
      err_hard_q     <= (err_hard_q & ~clear) | hard_stop;
      err_watchdog_q <= (err_watchdog_q & ~clear) | bite;
      irq_status_q   <= (irq_status_q & ~((wr && adr == `DDA_MOTION_IRQ_STATUS_ADDR) ? wsel[4:0] : 5'b00000))
                        | irq_set;
      if (wr && adr == `DDA_MOTION_IRQ_ENABLE_ADDR) irq_enable_q <= wdat[4:0];
      if (wr && adr == `DDA_MOTION_IRQ_LEVEL_ADDR) irq_level_q <= wdat[LW-1:0];
      done_count_q <= done_count_q + {31'd0, old_done} + {31'd0, new_done};
      done_wait_q  <= ~abort & (new_wait | (done_wait_q & tags_left));
      err_count_q  <= err_count_q + {31'd0, core_err};
      // A preset is the position before the steps of the same edge: a pulse that starts
      // on the edge of a preset counts from the preset value, so none is lost.
      pos_x_q <= (wr_pos_x ? wdat : pos_x_q) + dx;
      pos_y_q <= (wr_pos_y ? wdat : pos_y_q) + dy;
      if (Axes == 3) pos_z_q <= (wr_pos_z ? wdat : pos_z_q) + dz;
    end
  end
  assign irq_o = |(irq_status_q & irq_enable_q);

  // ---- the machine's inputs, the latches and the snapshot ----
  // Not built (Inputs 0): u_io is held in reset, so that every one of its flip-flops is a
  // constant synthesis removes, and the hierarchy and register names stay those of every
  // build. It then stops nothing, latches nothing and reads 0; the pins are not read.
  wire        err_estop, err_limit, probe_armed, probed;
  wire [31:0] io_rd;
  dda_motion_io #(.LW(LW), .Axes(Axes)) u_io (
    .clk_i        (clk_i),
    .rst_ni       (rst_ni & (Inputs != 0)),
    .estop_ni     (estop_ni),
    .limit_i      (limit_i),
    .home_i       (home_i),
    .probe_i      (probe_i),
    .wr_i         (wr),
    .adr_i        (adr),
    .wdat_i       (wdat),
    .clear_i      (clear),
    .snapshot_i   (wr_ctrl & wsel[`DDA_MOTION_CTRL_SNAPSHOT_LSB]),
    .probe_arm_i  (wr_ctrl & wsel[`DDA_MOTION_CTRL_PROBE_ARM_LSB]),
    .pos_x_i      (pos_x_q),
    .pos_y_i      (pos_y_q),
    .pos_z_i      (pos_z_q),
    .level_i      (level_q),
    .done_count_i (done_count_q),
    .step_i       (r_step),
    .dir_i        (r_dir),
    .pend_i       ({sz_pend, sy_pend, sx_pend}),
    .pdir_i       ({sz_pdir, sy_pdir, sx_pdir}),
    .hard_o       (io_hard),
    .soft_o       (io_soft),
    .err_o        (io_err),
    .probe_o      (io_probe),
    .home_o       (io_home),
    .err_estop_o  (err_estop),
    .err_limit_o  (err_limit),
    .probe_armed_o(probe_armed),
    .probed_o     (probed),
    .rd_o         (io_rd)
  );

  // ---- read data ----
  always @(*) begin
    rd = 32'd0;
    case (adr)
      `DDA_MOTION_ID_ADDR:      rd = `DDA_MOTION_ID_VALUE;
      `DDA_MOTION_VERSION_ADDR: rd = `DDA_MOTION_VERSION_VALUE;
      `DDA_MOTION_CONFIG_ADDR: begin
        rd[`DDA_MOTION_CONFIG_ENTRY_WORDS_LSB+:`DDA_MOTION_CONFIG_ENTRY_WORDS_WIDTH] = `DDA_MOTION_CONFIG_ENTRY_WORDS_WIDTH'(Words);
        rd[`DDA_MOTION_CONFIG_DEPTH_LOG2_LSB+:`DDA_MOTION_CONFIG_DEPTH_LOG2_WIDTH]   = `DDA_MOTION_CONFIG_DEPTH_LOG2_WIDTH'(DepthLog2);
        rd[`DDA_MOTION_CONFIG_ENTRY_ROWS_LSB+:`DDA_MOTION_CONFIG_ENTRY_ROWS_WIDTH]   = `DDA_MOTION_CONFIG_ENTRY_ROWS_WIDTH'(`DDA_MOTION_ENTRY_ROWS);
        rd[`DDA_MOTION_CONFIG_ACC_WIDTH_LSB+:`DDA_MOTION_CONFIG_ACC_WIDTH_WIDTH]     = `DDA_ACC_WIDTH;
        rd[`DDA_MOTION_CONFIG_CNT_WIDTH_LSB+:`DDA_MOTION_CONFIG_CNT_WIDTH_WIDTH]     = `DDA_CNT_WIDTH;
        rd[`DDA_MOTION_CONFIG_INPUTS_LSB]                                           = Inputs != 0;
        rd[`DDA_MOTION_CONFIG_AXES_LSB+:`DDA_MOTION_CONFIG_AXES_WIDTH]               = `DDA_MOTION_CONFIG_AXES_WIDTH'(Axes);
        rd[`DDA_MOTION_CONFIG_PACER_LSB]                                            = Pacer != 0;
      end
      `DDA_MOTION_STATUS_ADDR: begin
        rd[`DDA_MOTION_STATUS_BUSY_LSB]         = busy;
        rd[`DDA_MOTION_STATUS_EMPTY_LSB]        = empty;
        rd[`DDA_MOTION_STATUS_FULL_LSB]         = full;
        rd[`DDA_MOTION_STATUS_ERR_LSB]          = err_q;
        rd[`DDA_MOTION_STATUS_ERR_OVERFLOW_LSB] = err_overflow_q;
        rd[`DDA_MOTION_STATUS_ERR_PARTIAL_LSB]  = err_partial_q;
        rd[`DDA_MOTION_STATUS_ERR_STALL_LSB]    = err_stall_q;
        rd[`DDA_MOTION_STATUS_ABORTED_LSB]      = aborted_q;
        rd[`DDA_MOTION_STATUS_ERR_LANES_LSB]    = err_lanes_q;
        rd[`DDA_MOTION_STATUS_HOLDING_LSB]      = feed_hold_q & ~at_rest;
        rd[`DDA_MOTION_STATUS_HELD_LSB]         = feed_hold_q & at_rest;
        rd[`DDA_MOTION_STATUS_STOPPING_LSB]     = stopping_q;
        rd[`DDA_MOTION_STATUS_ERR_HARD_STOP_LSB] = err_hard_q;
        rd[`DDA_MOTION_STATUS_ERR_WATCHDOG_LSB] = err_watchdog_q;
        rd[`DDA_MOTION_STATUS_ERR_ESTOP_LSB]    = err_estop;
        rd[`DDA_MOTION_STATUS_ERR_LIMIT_LSB]    = err_limit;
        rd[`DDA_MOTION_STATUS_PROBE_ARMED_LSB]  = probe_armed;
        rd[`DDA_MOTION_STATUS_PROBED_LSB]       = probed;
        rd[`DDA_MOTION_STATUS_LEVEL_LSB+:`DDA_MOTION_STATUS_LEVEL_WIDTH] = level_q;
      end
      `DDA_MOTION_IRQ_STATUS_ADDR: rd[4:0] = irq_status_q;
      `DDA_MOTION_IRQ_ENABLE_ADDR: rd[4:0] = irq_enable_q;
      `DDA_MOTION_IRQ_LEVEL_ADDR:  rd[LW-1:0] = irq_level_q;
      `DDA_MOTION_DONE_COUNT_ADDR: rd = done_count_q;
      `DDA_MOTION_ERR_COUNT_ADDR:  rd = err_count_q;
      `DDA_MOTION_POS_X_ADDR:      rd = pos_x_q;
      `DDA_MOTION_POS_Y_ADDR:      rd = pos_y_q;
      `DDA_MOTION_POS_Z_ADDR:      rd = pos_z_q;
      `DDA_MOTION_ENTRY_MASK_ADDR: rd[Words-1:0] = mask_q;
      `DDA_MOTION_STEP_X_ADDR: begin
        rd[`DDA_MOTION_STEP_X_STEPLEN_LSB+:TW]   = steplen_x_q;
        rd[`DDA_MOTION_STEP_X_STEPSPACE_LSB+:TW] = stepspace_x_q;
      end
      `DDA_MOTION_DIR_X_ADDR: begin
        rd[`DDA_MOTION_DIR_X_DIRSETUP_LSB+:TW] = dirsetup_x_q;
        rd[`DDA_MOTION_DIR_X_DIRHOLD_LSB+:TW]  = dirhold_x_q;
      end
      `DDA_MOTION_STEP_Y_ADDR: begin
        rd[`DDA_MOTION_STEP_Y_STEPLEN_LSB+:TW]   = steplen_y_q;
        rd[`DDA_MOTION_STEP_Y_STEPSPACE_LSB+:TW] = stepspace_y_q;
      end
      `DDA_MOTION_DIR_Y_ADDR: begin
        rd[`DDA_MOTION_DIR_Y_DIRSETUP_LSB+:TW] = dirsetup_y_q;
        rd[`DDA_MOTION_DIR_Y_DIRHOLD_LSB+:TW]  = dirhold_y_q;
      end
      `DDA_MOTION_STEP_Z_ADDR: begin
        rd[`DDA_MOTION_STEP_Z_STEPLEN_LSB+:TW]   = steplen_z_q;
        rd[`DDA_MOTION_STEP_Z_STEPSPACE_LSB+:TW] = stepspace_z_q;
      end
      `DDA_MOTION_DIR_Z_ADDR: begin
        rd[`DDA_MOTION_DIR_Z_DIRSETUP_LSB+:TW] = dirsetup_z_q;
        rd[`DDA_MOTION_DIR_Z_DIRHOLD_LSB+:TW]  = dirhold_z_q;
      end
      `DDA_MOTION_POLARITY_ADDR: rd[5:0] = polarity_q;
      `DDA_MOTION_ACCEL_ADDR:    rd = accel_q;
      `DDA_MOTION_VMIN_ADDR:     rd = vmin_q;
      `DDA_MOTION_OVERRIDE_ADDR: rd[`DDA_MOTION_OVERRIDE_OVERRIDE_WIDTH-1:0] = override_q;
      `DDA_MOTION_WATCHDOG_ADDR: rd = wd_q;
      default: rd = io_rd;  // the machine's inputs, the latches, the snapshot (0 elsewhere)
    endcase
  end

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      ack_q <= 1'b0;
      dat_q <= 32'd0;
    end else begin
      ack_q <= req;
      if (req && !wb_we_i) dat_q <= rd;
    end
  end

endmodule
